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
                RenderSettings.DEFAULT.width(), RenderSettings.DEFAULT.height(), parentToWorld.open(), parentToWorld.close());
    }

    static int freeze(GObject o, Placement parentToWorld, Material inherited, int ids, AcceleratorKind kind) {
        return o.freeze(context(parentToWorld, inherited, kind), ids);
    }

    static int freeze(GObject o, Transform parentToWorld, Material inherited, int ids, AcceleratorKind kind) {
        return freeze(o, Placement.of(parentToWorld), inherited, ids, kind);
    }

    static int freeze(GObject o, Transform parentToWorld, Material inherited, int ids) {
        return freeze(o, parentToWorld, inherited, ids, AcceleratorKind.DEFAULT);
    }
}
