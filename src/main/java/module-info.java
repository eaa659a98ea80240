/**
 * Spindulys, a Whitted ray tracer for subdivision surfaces (Catmull-Clark, Loop and bilinear)
 * with CSG. Build a scene with {@link lt.spindulys.scene.SceneBuilder} (or parse one with
 * {@link lt.spindulys.io.SceneParser}), render it with {@link lt.spindulys.render.Renderer} and
 * write the image with {@link lt.spindulys.image.ImageWriter}.
 *
 * <p>Only the packages a library user needs are exported; the per-ray machinery (hit records,
 * traversal scratch, acceleration structures, shading, sampling), the command line and the bench stay inside.
 * The same jar also runs from the class path, where every package is visible.
 */
module lt.spindulys {
    // ImageIO for PNG/JPEG and texture images; transitive because the API hands out BufferedImages
    requires transitive java.desktop;
    requires java.management; // heap pools for the peak heap (render --stats, the bench), the JVM's options (the bench)
    requires jdk.management; // only for the bench: the process's CPU time (com.sun.management)
    // The wide BVH's vector box test: compiled against the incubating Vector API but optional at
    // run time, resolved only when the JVM is started with --add-modules jdk.incubator.vector;
    // without it WideBvh's probe falls back to the scalar binary BVH.
    requires static jdk.incubator.vector;

    exports lt.spindulys.camera;
    exports lt.spindulys.denoise;
    exports lt.spindulys.image;
    exports lt.spindulys.io;
    exports lt.spindulys.material;
    exports lt.spindulys.math;
    exports lt.spindulys.mesh;
    exports lt.spindulys.plugin;
    exports lt.spindulys.render;
    exports lt.spindulys.scene;
    exports lt.spindulys.subdiv;
    exports lt.spindulys.texture;

    // Output plugins of a viewer: the library's own are provided here, others found on the module path.
    uses lt.spindulys.plugin.OutputPlugin;
    provides lt.spindulys.plugin.OutputPlugin with
            lt.spindulys.plugin.obj.ObjExportPlugin,
            lt.spindulys.plugin.raytrace.RayTracePlugin;
}
