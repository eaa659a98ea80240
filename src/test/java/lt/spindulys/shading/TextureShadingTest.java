package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.scene.Sphere;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Planar;
import lt.spindulys.texture.Texture;
import lt.spindulys.texture.Uv;

/**
 * Texture channels against the untextured formulas: a 1x1 image looking straight down at the floor
 * y = 0 (as in {@link ShadingTermsTest}), with constant or recording textures.
 */
class TextureShadingTest {
    private static final PointLight LIGHT = new PointLight(new Vec3(3, 4, 0), Color.WHITE, 1, PointLight.Falloff.NONE);

    private static Texture constant(double r, double g, double b) {
        return (p, rgb) -> { rgb[0] = r; rgb[1] = g; rgb[2] = b; };
    }

    private static SceneBuilder floorScene(Material floor) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).ambient(Color.grey(0.5)).background(Color.BLACK).build())
                .camera(new PinholeCamera(new Vec3(0, 5, 0), Vec3.ZERO, Vec3.Z, 10))
                .light(LIGHT);
        b.add(new Plane(Vec3.Y, 0).material(floor));
        return b;
    }

    private static double[] render(SceneBuilder b) throws InterruptedException {
        var image = Renderer.render(b.build(), 1, ProgressListener.NONE).frame();
        return new double[] {image.get(0, 0, 0), image.get(0, 0, 1), image.get(0, 0, 2)};
    }

    private static void assertRgb(double[] expected, double[] actual) {
        for (int c = 0; c < 3; c++) assertEquals(expected[c], actual[c], 1e-9, "channel " + c);
    }

    private static Material.Builder floor() { return Material.builder().ka(0.2).kd(0.7).ks(0.5).shininess(12); }

    @Test
    void diffuseMultipliesTheColour() throws InterruptedException {
        double[] plain = render(floorScene(floor().color(new Color(0.4, 0.15, 0.9)).build()));
        double[] textured = render(floorScene(floor().color(new Color(0.8, 0.5, 0.9))
                .texture(Channel.DIFFUSE, constant(0.5, 0.3, 1), new Uv(1, 1)).build()));
        assertRgb(plain, textured);
    }

    @Test
    void specularScalesKsByTheMean() throws InterruptedException {
        double[] plain = render(floorScene(floor().ks(0.25).build()));
        double[] textured = render(floorScene(floor().texture(Channel.SPECULAR, constant(0.2, 0.5, 0.8), new Uv(1, 1)).build()));
        assertRgb(plain, textured);
    }

    /**
     * A mirror floor under a coloured sky (the background): its reflection, straight up, sees the
     * sky, so kr shows directly in the pixel. kr 0.8 textured by a texture of mean 0.5 is kr 0.4.
     */
    @Test
    void reflectionScalesKrByTheMean() throws InterruptedException {
        Color sky = new Color(0.3, 0.6, 0.9);
        double[] plain = render(mirrorScene(floor().kr(0.4).build(), sky));
        double[] full = render(mirrorScene(floor().kr(0.8).build(), sky));
        double[] textured = render(mirrorScene(floor().kr(0.8)
                .texture(Channel.REFLECTION, constant(0.2, 0.5, 0.8), new Uv(1, 1)).build(), sky));
        assertRgb(plain, textured);
        // The untextured kr 0.8 mirror shows 0.4 more of the sky: the texture did change kr.
        assertRgb(new double[] {textured[0] + 0.4 * 0.3, textured[1] + 0.4 * 0.6, textured[2] + 0.4 * 0.9}, full);
    }

    private static SceneBuilder mirrorScene(Material floor, Color sky) {
        SceneBuilder b = floorScene(floor);
        return b.settings(b.settings().toBuilder().background(sky).build());
    }

    @Test
    void emissionAddsItsColour() throws InterruptedException {
        double[] plain = render(floorScene(floor().build()));
        double[] textured = render(floorScene(floor().texture(Channel.EMISSION, constant(0.1, 0.2, 0.3), new Uv(1, 1)).build()));
        assertRgb(new double[] {plain[0] + 0.1, plain[1] + 0.2, plain[2] + 0.3}, textured);
    }

    @Test
    void transparencyTextureTintsShadows() throws InterruptedException {
        // A glass sphere between the light and the floor point; kt 0.8 textured by 0.5 -> 0.4.
        Material glass = Material.builder().kd(0).kt(0.8).ior(1).build();
        Material half = glass.toBuilder().texture(Channel.TRANSPARENCY, constant(0.5, 0.5, 0.5), new Uv(1, 1)).build();
        Material plainHalf = glass.toBuilder().kt(0.4).build();
        double[] a = render(withOccluder(half)), b = render(withOccluder(plainHalf));
        assertRgb(b, a);
        double[] none = render(floorScene(floor().build()));
        assertTrue(a[0] < none[0] && a[0] > 0.2 * 0.5 * 0.8, "shadow is partial: " + a[0] + " vs " + none[0]);
    }

    private static SceneBuilder withOccluder(Material m) {
        SceneBuilder b = floorScene(floor().build());
        b.add(new Sphere(new Vec3(1.5, 2, 0), 0.3).material(m)); // on the segment from (0,0,0) to the light (3,4,0)
        return b;
    }

    @Test
    void footprintGrowsWithDistanceAndPixelAngle() throws InterruptedException {
        double[] seen = new double[1];
        Texture probe = (p, rgb) -> { seen[0] = p.footprint; rgb[0] = rgb[1] = rgb[2] = 1; };
        Material m = floor().texture(Channel.DIFFUSE, probe, new Planar(Vec3.ZERO, Vec3.Y, Vec3.X, 1, 1)).build();
        render(floorScene(m));
        // One pixel of a 10 degree camera: the neighbouring pixel's ray is 2 tan(5) off the axis;
        // the floor is 5 away, seen head-on, planar scale 1.
        double angle = Math.atan(2 * Math.tan(Math.toRadians(5)));
        assertEquals(5 * angle, seen[0], 1e-9);
    }

    /**
     * A fine black-and-white checker image on a floor seen towards the horizon: with trilinear
     * filtering the footprint picks coarser mip levels with distance, so the far rows settle to
     * the mean grey; bilinear filtering keeps sampling single texels there and shimmers.
     */
    @Test
    void distantTrilinearTextureDoesNotShimmer() throws InterruptedException {
        int n = 64;
        double[] texels = new double[n * n * 3];
        for (int y = 0; y < n; y++) for (int x = 0; x < n; x++) java.util.Arrays.fill(texels, 3 * (y * n + x), 3 * (y * n + x) + 3, (x + y) % 2);
        lt.spindulys.texture.TextureImage img = lt.spindulys.texture.TextureImage.fromLinear(n, n, texels);
        double far = farRowSpread(img, lt.spindulys.texture.Filter.TRILINEAR);
        double aliased = farRowSpread(img, lt.spindulys.texture.Filter.BILINEAR);
        assertTrue(far < 0.025, "trilinear far rows vary by " + far);
        assertTrue(aliased > 0.08 && aliased > 4 * far, "bilinear far rows vary by only " + aliased + " (trilinear " + far + ")");
    }

    /** Standard deviation of the pixels in the image rows just below the horizon (emission only, so pixel = texture). */
    private static double farRowSpread(lt.spindulys.texture.TextureImage img, lt.spindulys.texture.Filter filter) throws InterruptedException {
        Texture t = new lt.spindulys.texture.ImageTexture(img, filter, lt.spindulys.texture.Wrap.REPEAT);
        Material m = Material.builder().ka(0).kd(0).texture(Channel.EMISSION, t, new Planar(Vec3.ZERO, Vec3.Y, Vec3.X, 1, 1)).build();
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(64, 64).background(Color.BLACK).build())
                .camera(new PinholeCamera(new Vec3(0, 1, 0), new Vec3(0, 0.7, 10), Vec3.Y, 40));
        b.add(new Plane(Vec3.Y, 0).material(m));
        var image = Renderer.render(b.build(), 1, ProgressListener.NONE).frame();
        double sum = 0, sum2 = 0;
        int count = 0;
        for (int y = 0; y < image.height(); y++) {
            double rowMean = 0;
            for (int x = 0; x < image.width(); x++) rowMean += image.get(x, y, 0);
            if (rowMean == 0) continue; // sky
            // The first few floor rows under the horizon: the farthest floor.
            for (int yy = y + 1; yy < y + 5; yy++) {
                for (int x = 0; x < image.width(); x++) {
                    double v = image.get(x, yy, 0);
                    sum += v;
                    sum2 += v * v;
                    count++;
                }
            }
            break;
        }
        double mean = sum / count;
        return Math.sqrt(Math.max(0, sum2 / count - mean * mean));
    }

    @Test
    void bumpTiltsTheNormalAgainstTheSlope() {
        // Height = x on the floor: the displaced surface is y = s x, whose normal is (-s, 1, 0).
        double s = 0.5;
        Texture ramp = (p, rgb) -> { rgb[0] = rgb[1] = rgb[2] = p.u; };
        Material m = Material.builder().bumpStrength(s).texture(Channel.BUMP, ramp, new Planar(Vec3.ZERO, Vec3.Y, Vec3.X, 1, 1)).build();
        TracerScratch scratch = new TracerScratch(2);
        ShadingData sd = new ShadingData();
        sd.setNormal(0, 1, 0);
        // A plane's parametrisation: u along +x, v along -z (so dpdu x dpdv = +y).
        sd.setDerivatives(1, 0, 0, 0, 0, -1);
        System.arraycopy(sd.dpdu, 0, sd.dpduObject, 0, 3);
        System.arraycopy(sd.dpdv, 0, sd.dpdvObject, 0, 3);
        sd.pObject[0] = 0.3; sd.pObject[2] = 0.7;
        TextureShading.evaluate(m, sd, 0.01, scratch, scratch.path[0]);
        double len = Math.hypot(s, 1);
        assertEquals(-s / len, sd.ns[0], 1e-9);
        assertEquals(1 / len, sd.ns[1], 1e-9);
        assertEquals(0, sd.ns[2], 1e-9);
        assertEquals(0, sd.ng[0], 0); // the geometric normal is untouched

        // The same with the parametrisation mirrored (dpdu x dpdv = -y): the tilt is the same.
        sd.setNormal(0, 1, 0);
        sd.setDerivatives(0, 0, -1, 1, 0, 0);
        System.arraycopy(sd.dpdu, 0, sd.dpduObject, 0, 3);
        System.arraycopy(sd.dpdv, 0, sd.dpdvObject, 0, 3);
        TextureShading.evaluate(m, sd, 0.01, scratch, scratch.path[0]);
        assertEquals(-s / len, sd.ns[0], 1e-9);
        assertEquals(1 / len, sd.ns[1], 1e-9);
    }

    @Test
    void theNormalPassShowsTheBumpedNormal() {
        double s = 0.5;
        Texture ramp = (p, rgb) -> { rgb[0] = rgb[1] = rgb[2] = p.u; };
        Material m = Material.builder().bumpStrength(s).texture(Channel.BUMP, ramp, new Planar(Vec3.ZERO, Vec3.Y, Vec3.X, 1, 1)).build();
        WhittedIntegrator w = new WhittedIntegrator(floorScene(m).build());
        double[] out = new double[4];
        w.traceFirstHit(new lt.spindulys.math.Ray().set(0.2, 5, 0.3, 0, -1, 0, 0, Double.POSITIVE_INFINITY), w.newScratch(), out);
        double len = Math.hypot(s, 1);
        assertEquals(5, out[0], 1e-9);
        assertEquals(-s / len, out[1], 1e-9);
        assertEquals(1 / len, out[2], 1e-9);
        assertEquals(0, out[3], 1e-9);
    }

    @Test
    void aChannelTakesOneTexture() {
        Material.Builder b = Material.builder().texture(Channel.DIFFUSE, constant(1, 1, 1), new Uv(1, 1));
        assertThrows(IllegalArgumentException.class, () -> b.texture(Channel.DIFFUSE, constant(1, 1, 1), new Uv(1, 1)));
        assertThrows(IllegalArgumentException.class, () -> b.texture(Channel.BUMP, null, new Uv(1, 1)));
        Material m = b.build();
        assertTrue(m.isTextured());
        assertTrue(m.toBuilder().build().texture(Channel.DIFFUSE) != null);
        assertTrue(!Material.DEFAULT.isTextured());
    }

    /** The surface TextureShading.evaluate leaves in a vertex for m, at a point of a flat floor (textures here are constant). */
    private static TracerScratch.PathVertex evaluated(Material m) {
        TracerScratch scratch = new TracerScratch(2);
        ShadingData sd = new ShadingData();
        sd.setNormal(0, 1, 0);
        sd.setDerivatives(1, 0, 0, 0, 0, -1);
        TracerScratch.PathVertex v = scratch.path[0];
        TextureShading.evaluate(m, sd, 0, scratch, v);
        return v;
    }

    private static Material.Builder principled() { return Material.builder().model(Material.Model.PRINCIPLED); }

    @Test
    void untexturedVertexTakesTheMaterialsValues() {
        TracerScratch.PathVertex v = evaluated(principled().metallic(0.3).roughness(0.2).transmission(0.6).emission(new Color(1, 2, 3)).build());
        assertRgb(new double[] {0.3, 0.2, 0.6}, new double[] {v.metallic, v.roughness, v.transmission});
        assertRgb(new double[] {1, 2, 3}, new double[] {v.emissionR, v.emissionG, v.emissionB});
        // A Whitted material's are set to what it returns: unused, but never stale.
        v = evaluated(Material.DEFAULT);
        assertRgb(new double[] {0, 0.5, 0}, new double[] {v.metallic, v.roughness, v.transmission});
        assertRgb(new double[] {0, 0, 0}, new double[] {v.emissionR, v.emissionG, v.emissionB});
    }

    @Test
    void emissionIsTheMaterialsPlusTheTexturesInBothModels() {
        for (Material.Builder b : new Material.Builder[] {Material.builder(), principled()}) {
            TracerScratch.PathVertex v = evaluated(b.emission(new Color(1, 2, 3)).texture(Channel.EMISSION, constant(0.25, 0.5, -0.5), new Uv(1, 1)).build());
            assertRgb(new double[] {1.25, 2.5, 2.5}, new double[] {v.emissionR, v.emissionG, v.emissionB});
        }
        // Without a material emission the texture's colour is the emission, bit for bit.
        TracerScratch.PathVertex v = evaluated(Material.builder().texture(Channel.EMISSION, constant(0.1, 0.2, 0.3), new Uv(1, 1)).build());
        assertEquals(List.of(0.1, 0.2, 0.3), List.of(v.emissionR, v.emissionG, v.emissionB));
    }

    @Test
    void roughnessAndMetallicTexturesScaleByTheMeanAndClamp() {
        java.util.function.Supplier<Material.Builder> b = () -> principled().roughness(0.5).metallic(0.8);
        TracerScratch.PathVertex v = evaluated(b.get().texture(Channel.ROUGHNESS, constant(0.2, 0.5, 0.8), new Uv(1, 1))
                .texture(Channel.METALLIC, constant(0.5, 0.5, 0.5), new Uv(1, 1)).build());
        assertEquals(0.25, v.roughness, 1e-15);
        assertEquals(0.4, v.metallic, 1e-15);
        // The product is clamped to [0, 1]: a texture may raise the value up to 1, never past it or below 0.
        v = evaluated(b.get().texture(Channel.ROUGHNESS, constant(1.6, 1.6, 1.6), new Uv(1, 1))
                .texture(Channel.METALLIC, constant(3, 3, 3), new Uv(1, 1)).build());
        assertEquals(0.8, v.roughness, 1e-15);
        assertEquals(1, v.metallic);
        v = evaluated(b.get().texture(Channel.ROUGHNESS, constant(-1, -1, -1), new Uv(1, 1)).build());
        assertEquals(0, v.roughness);
    }

    @Test
    void transparencyTextureScalesTransmissionAndKt() {
        Material m = principled().metallic(0.5).transmission(0.8).texture(Channel.TRANSPARENCY, constant(0.5, 0.5, 0.5), new Uv(1, 1)).build();
        TracerScratch.PathVertex v = evaluated(m);
        assertEquals(0.4, v.transmission, 1e-15);
        assertEquals(m.kt() * 0.5, v.kt, 1e-15); // the derived kt 0.4, halved
        // As a fraction: clamped to [0, 1].
        v = evaluated(principled().transmission(0.8).texture(Channel.TRANSPARENCY, constant(4, 4, 4), new Uv(1, 1)).build());
        assertEquals(0.8, v.transmission, 1e-15);
    }

    @Test
    void aTexturedBaseColourIsClampedToAReflectanceButAWhittedColourIsNot() {
        TracerScratch.PathVertex v = evaluated(principled().color(new Color(0.8, 0.5, 0.2)).texture(Channel.DIFFUSE, constant(2, 0.5, -1), new Uv(1, 1)).build());
        assertRgb(new double[] {1, 0.25, 0}, new double[] {v.colourR, v.colourG, v.colourB});
        v = evaluated(Material.builder().color(new Color(0.8, 0.5, 0.2)).texture(Channel.DIFFUSE, constant(2, 0.5, -1), new Uv(1, 1)).build());
        assertRgb(new double[] {1.6, 0.25, -0.2}, new double[] {v.colourR, v.colourG, v.colourB});
    }
}
