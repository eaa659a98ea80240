package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.PixelFilter;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.IntegratorKind;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.TextureImage;
import lt.spindulys.texture.Uniform;
import lt.spindulys.texture.Uv;

/**
 * Furnace tests of the path tracer: a surface that loses no energy, inside a uniform world of
 * radiance 1, must look exactly as bright as the world, 1 everywhere, whatever its shape and
 * BSDF; and a closed sphere of albedo a that emits E inside must look E / (1 - a) from within.
 * Any energy the integrator loses or invents (a wrong MIS weight or pdf, a throughput or
 * Russian roulette error, refraction's radiance scaling not undone) shows as a deviation that
 * the pixels' own spread bounds ({@link PixelStatistics}). The sphere is checked ring by ring
 * from its centre to its silhouette, since errors at grazing angles hide in a whole-image mean.
 */
class PathFurnaceTest {
    private static final int SIZE = 40, SAMPLES = 32;
    /** The camera's distance from the unit sphere and the tangent of half its field of view. */
    private static final double DISTANCE = 3, TAN_HALF = 0.5;
    /** Ring edges in units of the sphere's projected radius; the last ring is the background. */
    private static final double[] RINGS = {0, 0.5, 0.8, 0.95, 1.05, Double.POSITIVE_INFINITY};

    private static final Material WHITE_DIFFUSE = Material.builder().color(Color.WHITE).ka(0).kd(1).build();
    private static final Material SMOOTH_GLASS = Material.builder().color(Color.WHITE).ka(0).kd(0).kt(1).ior(1.5).fresnel(true).build();

    static TextureImage uniform(double v) {
        int w = 8, h = 4;
        double[] rgb = new double[3 * w * h];
        java.util.Arrays.fill(rgb, v);
        return TextureImage.fromLinear(w, h, rgb);
    }

    private static RenderSettings.Builder pathSettings(long seed) {
        // The box keeps every sample inside its pixel, so the rings of the sphere's silhouette stay where the test draws them.
        return RenderSettings.builder().size(SIZE, SIZE).samplesPerPixel(SAMPLES).seed(seed).maxDepth(64)
                .integrator(IntegratorKind.PATH).filter(PixelFilter.BOX);
    }

    /** The unit sphere of material m in a uniform environment of radiance 1, as a light (sampled with MIS) or only seen. */
    private static FrameBuffer furnace(Material m, boolean environmentIsLight, long seed) throws InterruptedException {
        SceneBuilder b = new SceneBuilder().settings(pathSettings(seed).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -DISTANCE), Vec3.ZERO, Vec3.Y, 2 * Math.toDegrees(Math.atan(TAN_HALF))))
                .environment(new Environment(uniform(1), 0, 1, environmentIsLight, 1));
        b.add(new Sphere(Vec3.ZERO, 1).material(m));
        return Renderer.render(b.build(), 2, ProgressListener.NONE).frame();
    }

    /** Which ring of {@link #RINGS} pixel (x, y)'s centre lies in. */
    private static int ring(int x, int y) {
        double sx = (2 * (x + 0.5) / SIZE - 1) * TAN_HALF, sy = (1 - 2 * (y + 0.5) / SIZE) * TAN_HALF;
        double tanAngularRadius = 1 / Math.sqrt(DISTANCE * DISTANCE - 1);
        double rho = Math.sqrt(sx * sx + sy * sy) / tanAngularRadius;
        int k = 0;
        while (rho >= RINGS[k + 1]) k++;
        return k;
    }

    /**
     * Asserts every channel of every pixel has expectation {@code expected[c]}: each ring's mean
     * within its standard error, and no pixel beyond {@link PixelStatistics#OUTLIER_SIGMAS} of
     * its ring's spread.
     */
    private static void assertFlat(FrameBuffer fb, double[] expected, String what) {
        for (int c = 0; c < 3; c++) {
            PixelStatistics[] rings = new PixelStatistics[RINGS.length - 1];
            for (int k = 0; k < rings.length; k++) rings[k] = new PixelStatistics();
            PixelStatistics all = new PixelStatistics();
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    double v = fb.get(x, y, c);
                    assertTrue(Double.isFinite(v), what + ": pixel " + x + "," + y + " is " + v);
                    rings[ring(x, y)].add(v);
                    all.add(v);
                }
            }
            all.assertMean(expected[c], what + ", channel " + c + ", whole image");
            for (int k = 0; k < rings.length; k++) {
                String ringName = what + ", channel " + c + ", ring " + RINGS[k] + ".." + RINGS[k + 1];
                rings[k].assertMean(expected[c], ringName);
                double bound = PixelStatistics.OUTLIER_SIGMAS * rings[k].standardDeviation() + PixelStatistics.ROUNDING * expected[c];
                for (int y = 0; y < SIZE; y++) {
                    for (int x = 0; x < SIZE; x++) {
                        if (ring(x, y) != k) continue;
                        double v = fb.get(x, y, c);
                        assertTrue(Math.abs(v - expected[c]) <= bound,
                                String.format("%s: pixel %d,%d is %.6f, more than %.2e from %.6f (%s)", ringName, x, y, v, bound, expected[c], rings[k]));
                    }
                }
            }
        }
    }

    private static final double[] ONE = {1, 1, 1};

    /**
     * Albedo 1, the environment only seen: every sample is exactly 1 (a cosine-sampled Lambert
     * bounce has weight albedo, then the sky), so any pixel off by more than rounding is a bug.
     */
    @Test
    void aWhiteDiffuseSphereDisappearsUnderAnUnlitSky() throws InterruptedException {
        assertFlat(furnace(WHITE_DIFFUSE, false, 1), ONE, "diffuse, sky only seen");
    }

    /** Albedo 1 under the sky as a light: next-event estimation and BSDF sampling weighted by MIS must sum to 1. */
    @Test
    void aWhiteDiffuseSphereDisappearsUnderASkyLight() throws InterruptedException {
        assertFlat(furnace(WHITE_DIFFUSE, true, 2), ONE, "diffuse, sky as a light");
    }

    /**
     * Half Lambert, half mirror (weights summing to 1, so lossless): the surface takes light
     * samples, but a path that picked the mirror must give the sky it finds the whole weight, and
     * the light sample must not count the mirror, or the sphere shows.
     */
    @Test
    void aDiffuseAndMirrorMixtureDisappearsUnderASkyLight() throws InterruptedException {
        Material half = Material.builder().color(Color.WHITE).ka(0).kd(0.5).kr(0.5).build();
        assertFlat(furnace(half, true, 6), ONE, "half diffuse, half mirror, sky as a light");
    }

    /**
     * Smooth glass (exact Fresnel, no absorption) loses nothing: the radiance scaling by 1/eta^2
     * going in is undone coming out, Russian roulette must keep the paths inside, and with 64
     * bounces every sample is again exactly 1. Both with the sky as a light (glass takes no light
     * samples, so the sky found by refraction must get the whole weight) and only seen.
     */
    @Test
    void smoothGlassDisappearsInAFurnace() throws InterruptedException {
        assertFlat(furnace(SMOOTH_GLASS, true, 3), ONE, "smooth glass, sky as a light");
        assertFlat(furnace(SMOOTH_GLASS, false, 4), ONE, "smooth glass, sky only seen");
    }

    /**
     * Rough glass (principled, transmission 1, roughness 0.3: GGX alpha 0.09) in a furnace. A
     * single-scattering microfacet model loses the light that would scatter between microfacets
     * (the whole image read 0.978); divided by its tabulated albedo it keeps it, so it reads 1.
     */
    @Test
    void roughGlassDisappearsInAFurnace() throws InterruptedException {
        Material rough = Material.builder().model(Material.Model.PRINCIPLED).color(Color.WHITE).transmission(1).roughness(0.3).ior(1.5).build();
        assertFlat(furnace(rough, true, 5), ONE, "rough glass, sky as a light");
        assertFlat(furnace(rough, false, 6), ONE, "rough glass, sky only seen");
    }

    /**
     * A white principled diffuse surface (roughness 1, no metal, no glass) under its dielectric
     * coat: the base takes what the rough coat's tabulated albedo leaves, so nothing is lost
     * (with the smooth Fresnel coupling it read 0.970).
     */
    @Test
    void whitePrincipledDiffuseDisappearsInAFurnace() throws InterruptedException {
        Material plastic = Material.builder().model(Material.Model.PRINCIPLED).color(Color.WHITE).roughness(1).build();
        assertFlat(furnace(plastic, true, 7), ONE, "white principled surface, sky as a light");
    }

    /**
     * The camera at the centre of a closed sphere whose inside emits E (a uniform texture on the
     * emission channel) and reflects diffusely with albedo a: the radiance is E (1 + a + a^2 + ...)
     * = E / (1 - a) everywhere, which exercises every bounce, the throughput channel by channel
     * and Russian roulette (a path's throughput falls below 1 here, unlike in the furnaces above).
     */
    @Test
    void insideAnEmittingSphereRadianceIsEmissionOverOneMinusAlbedo() throws InterruptedException {
        double[] albedo = {0.5, 0.8, 0.2};
        Color emission = new Color(0.3, 1, 2);
        Material walls = Material.builder().color(new Color(albedo[0], albedo[1], albedo[2])).ka(0).kd(1)
                .texture(Channel.EMISSION, new Uniform(emission), new Uv(1, 1)).build();
        SceneBuilder b = new SceneBuilder().settings(pathSettings(5).build())
                .camera(new PinholeCamera(Vec3.ZERO, new Vec3(0, 0, 1), Vec3.Y, 90));
        b.add(new Sphere(Vec3.ZERO, 2).material(walls));
        FrameBuffer fb = Renderer.render(b.build(), 2, ProgressListener.NONE).frame();
        double[] expected = {emission.r() / (1 - albedo[0]), emission.g() / (1 - albedo[1]), emission.b() / (1 - albedo[2])};
        assertFlat(fb, expected, "inside an emitting sphere");
    }
}
