package lt.spindulys.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.texture.TextureImage;

/**
 * The lights as the integrator samples them: each kind's sample agrees with its own density
 * (pdfLi of the sampled direction is the sample's pdf, and the weighted share is radiance over pdf
 * and samples), the density integrates to one over the directions, and rays see the nearest area
 * light's radiance.
 */
class LightsTest {
    private static final Color WARM = new Color(1, 0.5, 0.25);

    private static AreaLight rectangle(boolean oneSided) {
        return AreaLight.rectangle(new Vec3(0.3, 2, -0.2), new Vec3(0.2, -1, 0.1), Vec3.X, 2, 1.5, WARM, 3, oneSided, 4);
    }

    private static AreaLight disc() {
        return AreaLight.disc(new Vec3(-0.5, 1.5, 0.4), new Vec3(0, -1, 0.3), 1.2, WARM, 2, true, 3);
    }

    private static AreaLight sphere() {
        return AreaLight.sphere(new Vec3(0.4, 1.8, 0.1), 0.9, WARM, 5, 2);
    }

    /** A w x h map of seeded random values, a few texels bright. */
    private static TextureImage map(long seed, int w, int h) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] rgb = new double[3 * w * h];
        for (int i = 0; i < w * h; i++) {
            double bright = r.nextInt(10) == 0 ? 50 : 1;
            for (int c = 0; c < 3; c++) rgb[3 * i + c] = bright * r.nextDouble();
        }
        return TextureImage.fromLinear(w, h, rgb);
    }

    private static Lights lights(SceneBuilder b) { return Lights.of(b.build()); }

    private static Light only(AreaLight l) { return lights(new SceneBuilder().areaLight(l)).all()[0]; }

    private static Light environment() {
        Environment env = new Environment(map(7, 16, 8), 30, 1.5, true, 5);
        Light[] all = lights(new SceneBuilder().environment(env)).all();
        assertEquals(1, all.length);
        return all[0];
    }

    @Test
    void theLightsComeInShadingOrderEachAsItsKind() {
        SceneBuilder b = new SceneBuilder()
                .areaLight(sphere()).areaLight(rectangle(true)).areaLight(disc())
                .light(new PointLight(new Vec3(1, 2, 3), Color.WHITE))
                .environment(new Environment(map(3, 8, 4), 0, 1, true, 2));
        Lights lights = lights(b);
        Light[] all = lights.all();
        assertEquals(5, all.length);
        assertInstanceOf(PointSource.class, all[0]);
        assertInstanceOf(SphereSource.class, all[1]);
        assertInstanceOf(RectangleSource.class, all[2]);
        assertInstanceOf(DiscSource.class, all[3]);
        assertInstanceOf(EnvironmentSource.class, all[4]);
        assertEquals(4, lights.stratified(), "all but the point light take strata");
        assertTrue(lights.hasSurfaces());
        assertEquals(1, all[0].samples());
        assertEquals(2, all[1].samples());
        assertEquals(2, all[4].samples());
    }

    @Test
    void aPointLightIsADeltaThatFallsOff() {
        Light l = lights(new SceneBuilder().light(new PointLight(new Vec3(0, 3, 4), WARM, 10, PointLight.Falloff.INVERSE_SQUARE))).all()[0];
        assertTrue(l.isDelta());
        LightSample s = new LightSample();
        assertTrue(l.sampleLi(0, 0, 0, 0.3, 0.7, s));
        assertEquals(5, s.distance, 1e-12);
        assertEquals(0.6, s.wy, 1e-12);
        assertEquals(0.8, s.wz, 1e-12);
        assertEquals(10.0 / 25, s.r, 1e-12);
        assertEquals(0.25 * 10 / 25, s.b, 1e-12);
        assertEquals(s.r, s.weightedR);
        assertEquals(1, s.pdf);
        assertEquals(1, s.shadowTMax);
        assertTrue(s.delta);
        assertEquals(0, l.pdfLi(0, 0, 0, 0, 0.6, 0.8), "no direction drawn finds a point");
        assertFalse(l.sampleLi(0, 3, 4, 0.5, 0.5, s), "a point on the light gets nothing");
    }

    /** From several points, each sample's pdf is pdfLi of its direction, its share radiance / (pdf samples), its point at its distance. */
    @Test
    void everySampleAgreesWithTheDensityOfItsDirection() {
        SplittableRandom r = new SplittableRandom(11);
        LightSample s = new LightSample();
        for (Light l : new Light[] {only(rectangle(true)), only(rectangle(false)), only(disc()), only(sphere()), environment()}) {
            int drawn = 0;
            for (int i = 0; i < 2000; i++) {
                double px = r.nextDouble(-2, 2), py = r.nextDouble(-1, 1), pz = r.nextDouble(-2, 2);
                if (!l.sampleLi(px, py, pz, r.nextDouble(), r.nextDouble(), s)) continue;
                drawn++;
                String what = l.getClass().getSimpleName() + " from " + px + " " + py + " " + pz;
                assertFalse(s.delta);
                assertEquals(1, s.wx * s.wx + s.wy * s.wy + s.wz * s.wz, 1e-12, what);
                assertTrue(s.pdf > 0, what);
                assertEquals(s.pdf, l.pdfLi(px, py, pz, s.wx, s.wy, s.wz), 1e-6 * s.pdf, what);
                assertEquals(s.r / (s.pdf * l.samples()), s.weightedR, 1e-12 * s.weightedR, what);
                assertEquals(s.b / (s.pdf * l.samples()), s.weightedB, 1e-12 * s.weightedB, what);
                if (l instanceof EnvironmentSource) {
                    assertEquals(Double.POSITIVE_INFINITY, s.distance);
                } else {
                    assertEquals(s.x, px + s.distance * s.wx, 1e-9, what);
                    assertEquals(s.z, pz + s.distance * s.wz, 1e-9, what);
                    assertTrue(s.shadowTMax < 1 && s.shadowTMax > 1 - 1e-6, what);
                }
            }
            assertTrue(drawn > 1000, l.getClass().getSimpleName() + " drew " + drawn);
        }
    }

    /** The density over all directions, estimated with uniform directions: 1 (the lights are seen whole from the origin). */
    @Test
    void theDensityIntegratesToOne() {
        for (Light l : new Light[] {only(rectangle(true)), only(rectangle(false)), only(disc()), only(sphere()), environment()}) {
            SplittableRandom r = new SplittableRandom(5);
            int n = 1_000_000;
            double sum = 0;
            for (int i = 0; i < n; i++) {
                double z = 2 * r.nextDouble() - 1, phi = 2 * Math.PI * r.nextDouble(), sin = Math.sqrt(1 - z * z);
                sum += l.pdfLi(0, 0, 0, sin * Math.cos(phi), z, sin * Math.sin(phi));
            }
            assertEquals(1, sum * 4 * Math.PI / n, 0.02, l.getClass().getSimpleName());
        }
    }

    @Test
    void aOneSidedLightsBackGivesNoSampleAndHasNoDensity() {
        Light l = only(AreaLight.rectangle(new Vec3(0, 2, 0), new Vec3(0, 1, 0), Vec3.X, 1, 1, WARM, 1, true, 1));
        LightSample s = new LightSample();
        assertFalse(l.sampleLi(0, 0, 0, 0.5, 0.5, s), "the point is behind the light, which faces up");
        assertEquals(0, l.pdfLi(0, 0, 0, 0, 1, 0));
        assertTrue(l.sampleLi(0, 3, 0, 0.5, 0.5, s));
        assertEquals(1, s.pdf, 1e-12, "straight below a unit square at distance 1");
    }

    @Test
    void aRaySeesTheNearestAreaLightAndOnlyTheFrontOfAOneSidedOne() {
        Lights lights = lights(new SceneBuilder()
                .areaLight(AreaLight.rectangle(new Vec3(0, 3, 0), new Vec3(0, -1, 0), Vec3.X, 2, 2, WARM, 2, true, 1))
                .areaLight(AreaLight.sphere(new Vec3(0, 6, 0), 1, Color.WHITE, 7, 1)));
        double[] out = new double[4];
        Ray up = new Ray().set(0, 0, 0, 0, 2, 0, 0, Double.POSITIVE_INFINITY);
        assertEquals(0, lights.nearestSurface(up, Double.POSITIVE_INFINITY, out), "the rectangle, the first light");
        assertEquals(1.5, out[3], 1e-12, "the rectangle at y = 3, t = 1.5");
        assertEquals(2, out[0]);
        assertEquals(1, out[1]);
        assertEquals(0.5, out[2]);
        assertEquals(-1, lights.nearestSurface(up, 1, out), "a surface nearer than the light");
        Ray down = new Ray().set(0, 10, 0, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
        assertEquals(1, lights.nearestSurface(down, Double.POSITIVE_INFINITY, out), "the sphere");
        assertEquals(3, out[3], 1e-12, "the sphere's top");
        assertEquals(7, out[2]);
        Ray between = new Ray().set(0, 4, 0, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
        assertEquals(0, lights.nearestSurface(between, Double.POSITIVE_INFINITY, out));
        assertEquals(1, out[3], 1e-12);
        assertEquals(0, out[0], "the rectangle's back is black");
    }
}
