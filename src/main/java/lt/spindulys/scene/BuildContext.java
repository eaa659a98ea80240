package lt.spindulys.scene;

import java.util.Objects;

import lt.spindulys.camera.Camera;
import lt.spindulys.material.Material;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Transform;

/**
 * What an object is told when a scene is built ({@link GObject#freeze(BuildContext, int)}): where
 * its parent is placed, the material it inherits, the acceleration structure to build over its own
 * primitives, and the view: the camera, the film size in pixels and the shutter interval, so that
 * an object can do view-dependent work at build time (choose a level of detail from its projected
 * size, for example).
 *
 * <p>Immutable, so one context can be handed to many objects and to several threads. The scene
 * makes the first one from its settings and camera; a container (a {@link Bool}) derives one for
 * its operands with {@link #within}, which changes the placement and the material and keeps the
 * view. Object ids are not part of the context: they are the one value that flows back up (each
 * freeze returns the next free id), so they stay an argument and a return value.
 */
public final class BuildContext {
    private final Placement placement;
    private final Material material;
    private final AcceleratorKind accelerator;
    private final Camera camera;
    private final int width, height;
    private final double shutterOpen, shutterClose;
    private final BuildShared shared;

    BuildContext(Placement placement, Material material, AcceleratorKind accelerator, Camera camera,
                 int width, int height, double shutterOpen, double shutterClose, BuildShared shared) {
        this.placement = Objects.requireNonNull(placement);
        this.material = material;
        this.accelerator = Objects.requireNonNull(accelerator);
        this.camera = Objects.requireNonNull(camera);
        this.width = width;
        this.height = height;
        this.shutterOpen = shutterOpen;
        this.shutterClose = shutterClose;
        this.shared = Objects.requireNonNull(shared);
    }

    /**
     * The context of a scene's top-level objects: placed in world space over the settings'
     * shutter, inheriting the default material. A moving camera is the view halfway through the shutter.
     */
    static BuildContext of(RenderSettings settings, Camera camera) {
        double open = settings.shutterOpen(), close = settings.shutterClose();
        // A moving camera is seen standing where it is halfway through the shutter (the view that
        // chooses adaptive levels; the rays themselves move with it).
        if (camera instanceof lt.spindulys.camera.AnimatedCamera a) camera = a.at((open + close) / 2);
        return new BuildContext(Placement.of(Transform.IDENTITY, open, close), Material.DEFAULT,
                settings.accelerator(), camera, settings.width(), settings.height(), open, close,
                new BuildShared(settings.adaptive(), camera, settings.width(), settings.height()));
    }

    /**
     * The context for the children of a container: placed by {@code parentToWorld} and inheriting
     * {@code inherited} (null: none), with this context's structure kind, camera, film and shutter.
     */
    BuildContext within(Placement parentToWorld, Material inherited) {
        return new BuildContext(parentToWorld, inherited, accelerator, camera, width, height, shutterOpen, shutterClose, shared);
    }

    /** What every object of this scene build shares: adaptive tessellations, their cache and budget. */
    BuildShared shared() { return shared; }

    /**
     * The parent's object-to-world mapping: the object's own transform and motion are applied
     * before it. Its open and close times are the shutter's.
     *
     * @return the parent's object-to-world mapping, with the shutter's open and close times
     */
    public Placement placement() { return placement; }

    /**
     * The material the object inherits when it has none of its own: the enclosing CSG node's, or
     * {@link Material#DEFAULT} at the top; null for an object that is never shaded by itself.
     *
     * @return the inherited material, or null for an object never shaded by itself
     */
    public Material material() { return material; }

    /**
     * The kind of structure an object that indexes its own primitives (a mesh) builds over them.
     *
     * @return the acceleration structure kind for an object's own primitives
     */
    public AcceleratorKind accelerator() { return accelerator; }

    /**
     * The camera the scene is rendered through.
     *
     * @return the scene's camera
     */
    public Camera camera() { return camera; }

    /**
     * Width of the image in pixels.
     *
     * @return the image width, in pixels
     */
    public int width() { return width; }

    /**
     * Height of the image in pixels.
     *
     * @return the image height, in pixels
     */
    public int height() { return height; }

    /**
     * Start of the shutter interval, in the scene's time units (the time a ray may carry).
     *
     * @return the shutter opening time
     */
    public double shutterOpen() { return shutterOpen; }

    /**
     * End of the shutter interval, in the scene's time units.
     *
     * @return the shutter closing time
     */
    public double shutterClose() { return shutterClose; }
}
