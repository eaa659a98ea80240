package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Transform;

/**
 * Freezes an object in place, as a scene freezes its copies, for tests that query one object
 * without a scene: a context with the default camera and film and the placement's shutter.
 */
final class TestBuild {
    private TestBuild() {}

    static BuildContext context(Placement parentToWorld, Material inherited, AcceleratorKind kind) {
        return new BuildContext(parentToWorld, inherited, kind, SceneBuilder.DEFAULT_CAMERA,
                RenderSettings.DEFAULT.width(), RenderSettings.DEFAULT.height(), parentToWorld.open(), parentToWorld.close(),
                new BuildShared(AdaptiveSettings.DEFAULT, SceneBuilder.DEFAULT_CAMERA, RenderSettings.DEFAULT.width(), RenderSettings.DEFAULT.height()));
    }

    static int freeze(GObject o, Placement parentToWorld, Material inherited, int ids, AcceleratorKind kind) {
        BuildContext c = context(parentToWorld, inherited, kind);
        int next = o.freeze(c, ids);
        c.shared().finish(c); // adaptive surfaces choose their levels, as a scene has them do after placing all
        return next;
    }

    static int freeze(GObject o, Transform parentToWorld, Material inherited, int ids, AcceleratorKind kind) {
        return freeze(o, Placement.of(parentToWorld), inherited, ids, kind);
    }

    static int freeze(GObject o, Transform parentToWorld, Material inherited, int ids) {
        return freeze(o, parentToWorld, inherited, ids, AcceleratorKind.DEFAULT);
    }
}
