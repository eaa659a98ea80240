package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.GObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.scene.Sphere;
import lt.spindulys.trace.TraceContext;

/**
 * The integrator through CSG solids, on 1x1 images whose one camera ray is worked out by hand:
 * a transparent union is crossed once in and once out (shadows and refraction), the medium
 * entered through one leaf is left through another, and a difference shades and shadows its cut.
 */
class CsgShadingTest {
    private static final Color IA = new Color(0.5, 0.5, 0.5);
    private static final Color C = new Color(0.8, 0.6, 0.4);

    private static double[] render(SceneBuilder b) throws InterruptedException {
        var image = Renderer.render(b.build(), 1, ProgressListener.NONE).frame();
        return new double[] {image.get(0, 0, 0), image.get(0, 0, 1), image.get(0, 0, 2)};
    }

    private static Bool union(GObject... o) { return new Bool(Bool.Op.UNION, List.of(o)); }

    private static SceneBuilder floorScene(PointLight light) {
        return new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).ambient(IA).background(Color.BLACK).build())
                .camera(new PinholeCamera(new Vec3(0, 5, 0), Vec3.ZERO, Vec3.Z, 10))
                .light(light)
                .add(new Plane(Vec3.Y, 0).material(Material.builder().color(C).ka(0.2).kd(0.7).build()));
    }

    @Test
    void transparentUnionTintsAShadowOncePerCrossingOfTheWholeSolid() throws InterruptedException {
        PointLight light = new PointLight(new Vec3(6, 8, 0), Color.WHITE);
        double[] lit = render(floorScene(light));
        // Two overlapping spheres on the shadow ray (unit direction (0.6, 0.8, 0) from the origin):
        // the ray enters a at distance 3 and leaves b at distance 6, never crossing the inner parts.
        Color fa = new Color(1, 0.5, 0.25), fb = new Color(0.5, 1, 0.75);
        Material ma = Material.builder().kt(0.6).filter(fa).beta(0.3).ior(1.5).build();
        Material mb = Material.builder().kt(0.5).filter(fb).beta(0.7).ior(1.3).build();
        Sphere a = new Sphere(new Vec3(2.4, 3.2, 0), 1), b = new Sphere(new Vec3(3.0, 4.0, 0), 1);
        a.material(ma);
        b.material(mb);
        double[] shadowed = render(floorScene(light).add(union(a, b)));
        for (int c = 0; c < 3; c++) {
            double ambient = 0.2 * IA.get(c) * C.get(c);
            // Crossings: a's surface in, b's surface out; the medium is the one entered (a's) over 3.
            double t = 0.6 * fa.get(c) * 0.5 * fb.get(c) * Math.exp(-0.3 * 3);
            assertEquals((lit[c] - ambient) * t, shadowed[c] - ambient, 1e-9, "channel " + c);
        }
    }

    @Test
    void refractionThroughAUnionLeavesTheMediumItEntered() throws InterruptedException {
        // The camera ray runs along the axis of two overlapping spheres, entering a and leaving b
        // at normal incidence, then reaches the white background. Surfaces have no local terms.
        Color fa = new Color(1, 0.5, 0.25), fb = new Color(0.5, 1, 0.75);
        Material ma = Material.builder().ka(0).kd(0).kt(0.9).filter(fa).beta(0.2).ior(1.5).build();
        Material mb = Material.builder().ka(0).kd(0).kt(0.8).filter(fb).beta(0.6).ior(1.3).build();
        Sphere a = new Sphere(new Vec3(0, 0, 1), 1), b = new Sphere(new Vec3(0, 0, 2), 1);
        a.material(ma);
        b.material(mb);
        SceneBuilder s = new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).background(Color.WHITE).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 10))
                .add(union(a, b));
        double[] rgb = render(s);
        for (int c = 0; c < 3; c++) {
            // In through a (kt, filter), 3 units of a's medium, out through b, then nothing absorbs.
            double expected = 0.9 * fa.get(c) * Math.exp(-0.2 * 3) * 0.8 * fb.get(c);
            assertEquals(expected, rgb[c], 1e-9, "channel " + c);
        }
    }

    @Test
    void aNestedUnionIsOneMediumFromItsEntryToItsExit() throws InterruptedException {
        // union(union(a, b), c): three overlapping spheres on the camera ray's axis (normal
        // incidence, so no bending), a over z in [0, 2], b over [1, 3], c over [2.5, 4.5]. The ray
        // enters the whole solid through a at z = 0 and leaves it through c at z = 4.5; c belongs
        // to the outer union, a to the inner one, and both must count as surfaces of the one
        // outermost solid for the exit through c to leave the medium entered through a.
        Color fa = new Color(1, 0.5, 0.25), fc = new Color(0.5, 1, 0.75);
        Material ma = Material.builder().ka(0).kd(0).kt(0.9).filter(fa).beta(0.2).ior(1.5).build();
        Material mb = Material.builder().ka(0).kd(0).kt(0.7).beta(0.9).ior(1.1).build();
        Material mc = Material.builder().ka(0).kd(0).kt(0.8).filter(fc).beta(0.6).ior(1.3).build();
        Sphere a = new Sphere(new Vec3(0, 0, 1), 1), b = new Sphere(new Vec3(0, 0, 2), 1), c = new Sphere(new Vec3(0, 0, 3.5), 1);
        a.material(ma);
        b.material(mb);
        c.material(mc);
        SceneBuilder s = new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).background(Color.WHITE).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 10))
                .add(union(union(a, b), c));
        double[] rgb = render(s);
        for (int ch = 0; ch < 3; ch++) {
            // In through a (kt 0.9, filter fa), 4.5 units of a's medium (beta 0.2), out through c
            // (kt 0.8, filter fc), then the white background with nothing absorbing. Were c's exit
            // not taken as leaving a's medium, the ray would stay in it up to the background and
            // be absorbed entirely (e^(-0.2 * infinity)).
            double expected = 0.9 * fa.get(ch) * Math.exp(-0.2 * 4.5) * 0.8 * fc.get(ch);
            assertEquals(expected, rgb[ch], 1e-9, "channel " + ch);
        }
    }

    @Test
    void aNestedTransparentUnionTintsAShadowOncePerCrossingOfTheWholeSolid() throws InterruptedException {
        PointLight light = new PointLight(new Vec3(6, 8, 0), Color.WHITE);
        double[] lit = render(floorScene(light));
        // Three spheres on the shadow ray (unit direction (0.6, 0.8, 0) from the floor point at
        // the origin), centred at distances 4, 5 and 6.5 with radius 1: union(union(a, b), c) is
        // entered through a at distance 3 and left through c at distance 7.5 (the light is at 10).
        Color fa = new Color(1, 0.5, 0.25), fc = new Color(0.5, 1, 0.75);
        Material ma = Material.builder().kt(0.6).filter(fa).beta(0.3).ior(1.5).build();
        Material mb = Material.builder().kt(0.5).beta(0.9).ior(1.2).build();
        Material mc = Material.builder().kt(0.7).filter(fc).beta(0.5).ior(1.3).build();
        Sphere a = new Sphere(new Vec3(2.4, 3.2, 0), 1), b = new Sphere(new Vec3(3.0, 4.0, 0), 1), c = new Sphere(new Vec3(3.9, 5.2, 0), 1);
        a.material(ma);
        b.material(mb);
        c.material(mc);
        double[] shadowed = render(floorScene(light).add(union(union(a, b), c)));
        for (int ch = 0; ch < 3; ch++) {
            double ambient = 0.2 * IA.get(ch) * C.get(ch);
            // Crossings: a's surface in, c's surface out; a's medium (entered) over 7.5 - 3 = 4.5.
            double t = 0.6 * fa.get(ch) * 0.7 * fc.get(ch) * Math.exp(-0.3 * 4.5);
            assertEquals((lit[ch] - ambient) * t, shadowed[ch] - ambient, 1e-9, "channel " + ch);
        }
    }

    /**
     * A 24x24 image of a block of water made by a nested union of three spheres, in front of a
     * small wall, optionally with a transparent marble (kt 1, white filter, no local terms, the
     * water's absorption) of index {@code marbleIor} inside the water off the view axis.
     */
    private static double[] waterImage(double marbleIor) throws InterruptedException {
        // Rays caught inside the water by total internal reflection may meet the marble from any
        // side, and each marble crossing costs two levels of recursion but no weight: so that the
        // depth limit never cuts a path short in one image and not the other, every water surface
        // takes at least 0.4 of a ray's weight (kt 0.6, white at most) and the depth limit is the
        // largest allowed. A path falls below the contribution limit (0.001) after 14 water
        // surfaces, at most 14 + 2 * 15 levels deep, well within 64.
        Material water = Material.builder().ka(0).kd(0).kt(0.6).filter(new Color(0.7, 0.9, 1)).beta(0.1).ior(1.33).build();
        Sphere w1 = new Sphere(new Vec3(-0.3, 0, 0), 1.2), w2 = new Sphere(new Vec3(0.4, 0.2, 0.2), 1.1), w3 = new Sphere(new Vec3(0, -0.2, 0.5), 1.0);
        Bool block = union(union(w1, w2), w3);
        block.material(water);
        Box wall = new Box(new Vec3(-0.5, -0.5, 4), new Vec3(0.5, 0.5, 4.2));
        wall.material(Material.builder().color(C).ka(1).kd(0).build());
        SceneBuilder s = new SceneBuilder()
                .settings(RenderSettings.builder().size(24, 24).maxDepth(64).ambient(Color.WHITE).background(new Color(0.1, 0.2, 0.3)).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 30))
                .add(block).add(wall);
        if (marbleIor > 0) {
            // Wholly inside w1 (distance 0.65 + radius 0.45 < 1.2 from its centre).
            Sphere marble = new Sphere(new Vec3(0.2, 0.25, -0.3), 0.45);
            marble.material(Material.builder().ka(0).kd(0).kt(1).beta(0.1).ior(marbleIor).build());
            s.add(marble);
        }
        return Renderer.render(s.build(), 1, ProgressListener.NONE).frame().data().clone();
    }

    @Test
    void nestedTransparentObjectsKeepTheRightIndexOfRefractionOnEachSide() throws InterruptedException {
        // A marble inside the water bends a ray by the indices on its two sides, water's and its
        // own. Of the water's index it bends nothing, and since it passes everything (kt 1, white
        // filter) and absorbs like the water, the image is the water's alone, up to rounding
        // (the rays through it are re-aimed and restarted at its surfaces). Taking air (index 1)
        // for either side of the marble's surfaces would bend the rays through it.
        double[] water = waterImage(0);
        double[] same = waterImage(1.33);
        assertEquals(0, maxDifference(water, same), 1e-9, "a marble of the water's index must not show");
        double[] denser = waterImage(1.8);
        assertTrue(maxDifference(water, denser) > 0.05, "a denser marble bends the rays through it");
    }

    /** A 24x24 image of a union of two transparent spheres in front of a checkered wall. */
    private static double[] unionImage(double iorA, double iorB) throws InterruptedException {
        Material ma = Material.builder().ka(0).kd(0).kt(0.9).ior(iorA).build();
        Material mb = Material.builder().ka(0).kd(0).kt(0.8).filter(new Color(0.5, 1, 0.75)).ior(iorB).build();
        // b bulges out of a's back, hidden behind a as seen from the camera.
        Sphere a = new Sphere(new Vec3(0, 0, 0), 1.2), b = new Sphere(new Vec3(0.1, 0.1, 1.0), 0.8);
        a.material(ma);
        b.material(mb);
        Box wall = new Box(new Vec3(-0.5, -0.5, 4), new Vec3(0.5, 0.5, 4.2));
        wall.material(Material.builder().color(C).ka(1).kd(0).build());
        SceneBuilder s = new SceneBuilder()
                .settings(RenderSettings.builder().size(24, 24).ambient(Color.WHITE).background(new Color(0.1, 0.2, 0.3)).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 30))
                .add(union(a, b)).add(wall);
        return Renderer.render(s.build(), 1, ProgressListener.NONE).frame().data().clone();
    }

    @Test
    void theMediumEnteredGivesTheIndexOnBothCrossings() throws InterruptedException {
        // Every camera ray enters through a and leaves through b or a: the inside is a's medium,
        // so b's own index never matters, while a's bends the rays through the solid.
        double[] base = unionImage(1.5, 1.3);
        assertEquals(0, maxDifference(base, unionImage(1.5, 1.9)), 0, "b's index must not matter");
        double[] other = unionImage(1.2, 1.3);
        assertTrue(maxDifference(base, other) > 0.05, "a's index bends the rays");
    }

    private static double maxDifference(double[] x, double[] y) {
        double m = 0;
        for (int i = 0; i < x.length; i++) m = Math.max(m, Math.abs(x[i] - y[i]));
        return m;
    }

    /** A hollow glass ball: a sphere minus a concentric one of half its radius, the glass given to the difference. */
    private static Bool hollowBall(Vec3 centre, double radius, Material glass) {
        Bool d = new Bool(Bool.Op.DIFFERENCE, List.of(new Sphere(centre, radius), new Sphere(centre, radius / 2)));
        d.material(glass);
        return d;
    }

    @Test
    void theCutOfATransparentDifferenceFacesOutOfTheResult() throws InterruptedException {
        // Shading turns every normal towards the viewer, so an opaque cut looks the same whichever
        // way its normal points; what the outward normal decides is whether a ray crossing the
        // cut enters or leaves the medium. The subtracted sphere's own outward normal points into
        // the glass; flipped (as documented) it points out of the result, into the cavity.
        Color f = new Color(1, 0.5, 0.25);
        Material glass = Material.builder().ka(0).kd(0).kt(0.9).filter(f).beta(0.4).ior(1.5).build();
        Scene scene = new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).background(Color.WHITE).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 10))
                .add(hollowBall(Vec3.ZERO, 1, glass)).build();
        // Through the scene: from the middle of the cavity the first surface is the cut, and its
        // outward normal points back towards the ray's origin (out of the glass into the cavity).
        Ray fromCavity = new Ray().set(0, 0, 0, 0.3, -0.4, 0.5, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit();
        assertTrue(scene.intersect(fromCavity, h, new TraceContext()));
        ShadingData sd = new ShadingData();
        h.object.shade(fromCavity, h, sd);
        double len = Math.sqrt(0.5);
        for (int c = 0; c < 3; c++) assertEquals(-new double[] {0.3, -0.4, 0.5}[c] / len, sd.ng[c], 1e-12, "normal " + c);
        // Rendered: the camera ray runs through the centre at normal incidence: into the glass at
        // z = -1, out into the cavity at -0.5, into the glass again at 0.5, out at 1. Four
        // crossings (kt 0.9, filter f each) and 1 unit of glass (beta 0.4); the cavity is air.
        // Taken the other way round, the cut would be an entry at -0.5 and an exit at 0.5, and
        // the cavity would absorb as glass: twice the absorption.
        double[] rgb = render(new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).background(Color.WHITE).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 10))
                .add(hollowBall(Vec3.ZERO, 1, glass)));
        // (1e-8: each of the four restarts is offset from its surface by about 1e-9.)
        for (int c = 0; c < 3; c++) {
            double expected = Math.pow(0.9 * f.get(c), 4) * Math.exp(-0.4 * 1);
            assertEquals(expected, rgb[c], 1e-8, "camera, channel " + c);
        }
        // A shadow ray through a hollow ball centred on it at distance 5 (unit direction
        // (0.6, 0.8, 0) from the floor point at the origin): glass over [4, 4.5] and [5.5, 6], the
        // same four crossings and 1 unit of glass.
        Material shadowGlass = Material.builder().kt(0.9).filter(f).beta(0.4).ior(1.5).build();
        PointLight light = new PointLight(new Vec3(6, 8, 0), Color.WHITE);
        double[] lit = render(floorScene(light));
        double[] shadowed = render(floorScene(light).add(hollowBall(new Vec3(3, 4, 0), 1, shadowGlass)));
        for (int c = 0; c < 3; c++) {
            double ambient = 0.2 * IA.get(c) * C.get(c);
            double t = Math.pow(0.9 * f.get(c), 4) * Math.exp(-0.4 * 1);
            assertEquals((lit[c] - ambient) * t, shadowed[c] - ambient, 1e-8, "shadow, channel " + c);
        }
    }

    @Test
    void differenceShadesItsCutAndShadowsItself() throws InterruptedException {
        // A box with a spherical bowl cut into its top; the camera looks straight down at the
        // bowl's bottom (y = 0.2), whose normal is the subtracted sphere's, flipped to face up.
        Material m = Material.builder().color(C).ka(0.2).kd(0.7).build();
        Bool bowl = new Bool(Bool.Op.DIFFERENCE, List.of(new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1)), new Sphere(new Vec3(0, 1, 0), 0.8)));
        bowl.material(m);
        SceneBuilder above = new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).ambient(IA).background(Color.BLACK).build())
                .camera(new PinholeCamera(new Vec3(0, 5, 0), Vec3.ZERO, Vec3.Z, 10))
                .light(new PointLight(new Vec3(0, 10, 0), Color.WHITE, 1, PointLight.Falloff.NONE))
                .add(bowl);
        double[] lit = render(above);
        for (int c = 0; c < 3; c++) assertEquals(0.2 * IA.get(c) * C.get(c) + 0.7 * C.get(c), lit[c], 1e-9, "channel " + c);
        // A low light: the shadow ray leaves the bowl through its wall into the box's solid part.
        Bool bowl2 = new Bool(Bool.Op.DIFFERENCE, List.of(new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1)), new Sphere(new Vec3(0, 1, 0), 0.8)));
        bowl2.material(m);
        SceneBuilder low = new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).ambient(IA).background(Color.BLACK).build())
                .camera(new PinholeCamera(new Vec3(0, 5, 0), Vec3.ZERO, Vec3.Z, 10))
                .light(new PointLight(new Vec3(5, 1.5, 0), Color.WHITE, 1, PointLight.Falloff.NONE))
                .add(bowl2);
        double[] shadowed = render(low);
        for (int c = 0; c < 3; c++) assertEquals(0.2 * IA.get(c) * C.get(c), shadowed[c], 1e-12, "channel " + c);
    }
}
