package lt.spindulys.shading;

import lt.spindulys.math.Ray;
import lt.spindulys.scene.Hit;
import lt.spindulys.scene.Material;
import lt.spindulys.scene.ShadingData;
import lt.spindulys.scene.TraceContext;

/**
 * Per-thread scratch of the integrator: one ray, hit, shading record and colour per recursion
 * depth (the recursion is depth-first, so a level's scratch is free again when it returns), the
 * stack of media the current ray is inside, and ray counters. Never shared between threads.
 */
public final class TracerScratch {
    public final TraceContext ctx = new TraceContext();
    final Ray[] rays;
    final Hit[] hits;
    final ShadingData[] shading;
    final double[][] colour;
    final double[] dir = new double[3];
    final Ray shadowRay = new Ray();
    final Hit shadowHit = new Hit();
    final ShadingData shadowShading = new ShadingData();
    final double[] transmission = new double[3];

    // Media the ray is inside, innermost last.
    Material[] media = new Material[8];
    int mediaCount;

    /** Rays traced, by kind (counted per thread and summed by the renderer). */
    public long cameraRays, shadowRays, reflectionRays, refractionRays;

    public TracerScratch(int maxDepth) {
        int levels = maxDepth + 2;
        rays = new Ray[levels];
        hits = new Hit[levels];
        shading = new ShadingData[levels];
        colour = new double[levels][3];
        for (int i = 0; i < levels; i++) {
            rays[i] = new Ray();
            hits[i] = new Hit();
            shading[i] = new ShadingData();
        }
    }

    void pushMedium(Material m) {
        if (mediaCount == media.length) media = java.util.Arrays.copyOf(media, media.length * 2);
        media[mediaCount++] = m;
    }

    Material innermost() { return mediaCount == 0 ? null : media[mediaCount - 1]; }

    /** The medium enclosing the innermost one (what a ray leaving the innermost enters). */
    Material outer() { return mediaCount < 2 ? null : media[mediaCount - 2]; }
}
