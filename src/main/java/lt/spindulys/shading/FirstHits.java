package lt.spindulys.shading;

import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.camera.PixelFootprint;
import lt.spindulys.material.Material;
import lt.spindulys.math.Ray;
import lt.spindulys.scene.Scene;
import lt.spindulys.texture.Channel;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;

/**
 * What every integrator shares: the first hit along a ray as the render passes show it, and the
 * footprint of a texture lookup from the camera's pixel footprint. Immutable.
 */
final class FirstHits {
    private final Scene scene;
    /** How wide a pixel's footprint is at a distance along the camera's rays (texture footprints). */
    private final PixelFootprint pixel;

    FirstHits(Scene scene) {
        this.scene = scene;
        this.pixel = pixelFootprint(scene);
    }

    /**
     * The camera's pixel footprint for this scene's image size (see
     * {@link lt.spindulys.camera.Camera#pixelFootprint}); none without a camera.
     */
    static PixelFootprint pixelFootprint(Scene scene) {
        if (scene.camera() == null) return new PixelFootprint(0, 0);
        return scene.camera().pixelFootprint(scene.settings().width(), scene.settings().height());
    }

    /** Smallest incidence cosine used to widen a texture footprint on surfaces seen at a grazing angle. */
    private static final double MIN_FOOTPRINT_COSINE = 1 / lt.spindulys.texture.Mapping.MAX_ANISOTROPY;

    /**
     * What a render pass sees along {@code ray}: its first hit only, with no lights, shadows or
     * secondary rays. Writes to out[0] the distance along the ray's direction made unit
     * (+Infinity if nothing is hit) and to out[1..3] the unit world-space shading normal turned to
     * face the ray, by the same rule as shading uses (0 0 0 if nothing is hit).
     *
     * @return the {@link lt.spindulys.scene.GObject#id()} of the object hit, or -1
     */
    int trace(Ray ray, TracerScratch s, double[] out) {
        s.cameraRays++;
        if (TraversalScratch.COUNTING) s.ctx.rayKind = TraversalScratch.CAMERA;
        TracerScratch.PathVertex v = s.path[0];
        Hit hit = v.hit;
        if (!scene.intersect(ray, hit, s.ctx)) {
            out[0] = Double.POSITIVE_INFINITY;
            out[1] = out[2] = out[3] = 0;
            return -1;
        }
        ShadingData sd = v.shading;
        hit.object.shade(ray, hit, sd);
        double dlen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        double dx = ray.dx / dlen, dy = ray.dy / dlen, dz = ray.dz / dlen;
        // The normal pass shows the bumped normal that shading uses.
        if (sd.material.texture(Channel.BUMP) != null) TextureShading.evaluate(sd.material, sd, footprint(sd, hit.t * dlen, dx, dy, dz), s, v);
        out[0] = hit.t * dlen;
        facingNormal(sd, dx, dy, dz, out, 1);
        return hit.object.id();
    }

    /**
     * Writes to out[at..at + 2] the shading normal of {@code sd} turned to face a ray along unit
     * direction d, by the rule shading uses: both normals flipped towards the ray by the
     * geometric one, and the geometric normal where the interpolated one still faces away.
     */
    private static void facingNormal(ShadingData sd, double dx, double dy, double dz, double[] out, int at) {
        double sign = sd.ng[0] * dx + sd.ng[1] * dy + sd.ng[2] * dz < 0 ? 1 : -1;
        double nx = sign * sd.ns[0], ny = sign * sd.ns[1], nz = sign * sd.ns[2];
        if (nx * dx + ny * dy + nz * dz >= 0) { nx = sign * sd.ng[0]; ny = sign * sd.ng[1]; nz = sign * sd.ng[2]; }
        out[at] = nx; out[at + 1] = ny; out[at + 2] = nz;
    }

    /**
     * Records, when asked, the first hit of a camera ray along unit direction d, which hit
     * {@code sd} at {@code distance}, in {@link TracerScratch#features}: the albedo (a principled
     * material's base colour; a Whitted one's kd colour + kr + kt filter, each channel clamped to
     * 1: the tint of what it reflects and transmits, so a mirror or glass has an albedo too, its
     * specular tint, instead of OIDN's following the path to the next rough surface), the shading
     * normal facing the ray ({@link #facingNormal}) and 1 / distance. The vertex's textured terms
     * must be evaluated.
     */
    static void recordHit(TracerScratch s, TracerScratch.PathVertex v, ShadingData sd, double dx, double dy, double dz, double distance) {
        if (!s.recordFeatures) return;
        double[] f = s.features;
        Material m = sd.material;
        if (m.model() == Material.Model.PRINCIPLED) {
            f[0] = v.colourR; f[1] = v.colourG; f[2] = v.colourB;
        } else {
            double kd = m.kd(), kr = v.kr, kt = v.kt;
            lt.spindulys.math.Color filter = m.filter();
            f[0] = Math.min(1, kd * v.colourR + kr + kt * filter.r());
            f[1] = Math.min(1, kd * v.colourG + kr + kt * filter.g());
            f[2] = Math.min(1, kd * v.colourB + kr + kt * filter.b());
        }
        facingNormal(sd, dx, dy, dz, f, 3);
        f[6] = distance > 0 ? 1 / distance : 0;
    }

    /** Records, when asked, that a camera ray saw no surface (the sky, the background or a light's surface). */
    static void recordNothing(TracerScratch s) {
        if (s.recordFeatures) java.util.Arrays.fill(s.features, 0);
    }

    /** World-space width of the pixel's footprint at a hit a path of this length reaches along unit direction d. */
    double footprint(ShadingData sd, double travelled, double dx, double dy, double dz) {
        double cos = Math.abs(sd.ng[0] * dx + sd.ng[1] * dy + sd.ng[2] * dz);
        return pixel.at(travelled) / Math.max(cos, MIN_FOOTPRINT_COSINE);
    }

}
