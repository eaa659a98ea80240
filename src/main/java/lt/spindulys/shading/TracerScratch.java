package lt.spindulys.shading;

import lt.spindulys.math.Ray;
import lt.spindulys.trace.TracedObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.material.Material;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.texture.TexturePoint;

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
    /** Distance travelled from the camera to the origin of the ray at each depth (for texture footprints). */
    final double[] travelled;
    // Texture evaluation (TextureShading): the point handed to textures, colour and scalar
    // scratch, a shifted object point for bump differences, and the textured surface terms.
    final TexturePoint texPoint = new TexturePoint();
    final double[] texRgb = new double[3];
    final double[] texScratch = new double[3];
    final double[] texObject = new double[3];
    /** Surface terms after textures: colour r g b, ks, kr, kt, emission r g b. */
    final double[] terms = new double[9];

    // Media the ray is inside, innermost last: the material it entered by and the solid
    // (TracedObject.solid()) it entered, so leaving through another surface of the same CSG solid
    // leaves the same medium.
    Material[] media = new Material[8];
    TracedObject[] solids = new TracedObject[8];
    int mediaCount;

    /** Rays traced, by kind (counted per thread and summed by the renderer). */
    public long cameraRays, shadowRays, reflectionRays, refractionRays;

    public TracerScratch(int maxDepth) {
        int levels = maxDepth + 2;
        rays = new Ray[levels];
        hits = new Hit[levels];
        shading = new ShadingData[levels];
        colour = new double[levels][3];
        travelled = new double[levels];
        for (int i = 0; i < levels; i++) {
            rays[i] = new Ray();
            hits[i] = new Hit();
            shading[i] = new ShadingData();
        }
    }

    void pushMedium(Material m, TracedObject solid) {
        if (mediaCount == media.length) {
            media = java.util.Arrays.copyOf(media, media.length * 2);
            solids = java.util.Arrays.copyOf(solids, solids.length * 2);
        }
        solids[mediaCount] = solid;
        media[mediaCount++] = m;
    }

    Material innermost() { return mediaCount == 0 ? null : media[mediaCount - 1]; }

    /** The solid of the innermost medium, or null outside every medium. */
    TracedObject innermostSolid() { return mediaCount == 0 ? null : solids[mediaCount - 1]; }

    /** The medium enclosing the innermost one (what a ray leaving the innermost enters). */
    Material outer() { return mediaCount < 2 ? null : media[mediaCount - 2]; }
}
