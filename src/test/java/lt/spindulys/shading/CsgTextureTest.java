package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.GObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.scene.Sphere;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Mapping;
import lt.spindulys.texture.Planar;
import lt.spindulys.texture.Texture;
import lt.spindulys.texture.TexturePoint;

/**
 * A CSG block's own material maps textures in the block's space (one solid), an operand's own
 * material in the operand's. The textures here record what they are given: a planar one its
 * (u, v), a solid one its point, so the shaded colour is the mapping's input.
 */
class CsgTextureTest {
    private static final Texture RECORD_UV = (p, rgb) -> { rgb[0] = p.u; rgb[1] = p.v; rgb[2] = 0; };
    private static final Texture RECORD_POINT = (p, rgb) -> { rgb[0] = p.x; rgb[1] = p.y; rgb[2] = p.z; };
    private static final Mapping PLANAR = new Planar(Vec3.ZERO, Vec3.Z, Vec3.X, 0.5, 0.5);
    /** Where the blocks are placed: turned and moved, so block, operand and world spaces all differ. */
    private static final Transform PLACE = Transform.rotateY(30).then(Transform.rotateX(-15)).then(Transform.translate(2, 0.5, 3));

    private static Material textured(Texture t) {
        return Material.builder().color(Color.WHITE).texture(Channel.DIFFUSE, t, PLANAR).build();
    }

    /** A 1 x 2 x 2 box centred on the origin of its own space, moved to x = dx. */
    private static Box half(double dx) {
        return (Box) new Box(new Vec3(-0.5, -1, -1), new Vec3(0.5, 1, 1)).transform(Transform.translate(dx, 0, 0));
    }

    private record Shaded(GObject object, double[] rgb, ShadingData sd) {}

    /** Shades the hit of the ray that reaches block-space point p from block-space direction -z. */
    private static Shaded shade(Scene scene, Transform blockToWorld, Vec3 p) {
        return shade(scene, blockToWorld, p, new Ray().time);
    }

    /** {@link #shade(Scene, Transform, Vec3)} with a ray at {@code time} (blockToWorld: the block's placement then). */
    private static Shaded shade(Scene scene, Transform blockToWorld, Vec3 p, double time) {
        Vec3 o = blockToWorld.point(p.plus(new Vec3(0, 0, -5))), d = blockToWorld.vector(Vec3.Z);
        Ray ray = new Ray(o, d);
        ray.time = time;
        TracerScratch s = new TracerScratch(8);
        Hit hit = new Hit();
        assertTrue(scene.intersect(ray, hit, s.ctx));
        ShadingData sd = new ShadingData();
        hit.object.shade(ray, hit, sd);
        TracerScratch.PathVertex v = s.path[0];
        TextureShading.evaluate(sd.material, sd, 0, s, v);
        return new Shaded((GObject) hit.object, new double[] {v.colourR, v.colourG, v.colourB}, sd);
    }

    /** The recorded texture's colour for block-space point p: the mapping evaluated there. */
    private static double[] expected(Texture t, Vec3 p) {
        TexturePoint tp = new TexturePoint();
        PLANAR.map(0, 0, new double[3], new double[3], new double[] {p.x(), p.y(), p.z()}, tp);
        double[] rgb = new double[3];
        t.evaluate(tp, rgb);
        return rgb;
    }

    private static void assertRgb(double[] expected, double[] actual, String what) {
        for (int c = 0; c < 3; c++) assertEquals(expected[c], actual[c], 1e-9, what + ", channel " + c);
    }

    @Test
    void abuttingBoxesUnderOnePlanarTextureShowOneTexture() {
        Box left = half(-0.5), right = half(0.5);
        Bool union = new Bool(Bool.Op.UNION, List.of(left, right));
        union.material(textured(RECORD_UV)).transform(PLACE);
        Scene scene = new SceneBuilder().add(union).build();
        // Hits name the scene's own frozen copies of the operands.
        List<GObject> built = ((Bool) scene.objects().get(0)).operands();
        // Either side of the seam at x = 0 on the front face z = -1, and far from it.
        for (double x : new double[] {-1e-6, 1e-6, -0.9, 0.9, -0.3, 0.4}) {
            Vec3 p = new Vec3(x, 0.3, -1);
            Shaded h = shade(scene, PLACE, p);
            assertSame(built.get(x < 0 ? 0 : 1), h.object());
            assertRgb(expected(RECORD_UV, p), h.rgb(), "x " + x);
            // Bump frames follow: the derivatives given to the mapping are the block-space ones.
            Vec3 du = PLACE.inverse().vector(new Vec3(h.sd().dpdu[0], h.sd().dpdu[1], h.sd().dpdu[2]));
            assertEquals(du.x(), h.sd().dpduObject[0], 1e-12);
            assertEquals(du.y(), h.sd().dpduObject[1], 1e-12);
            assertEquals(du.z(), h.sd().dpduObject[2], 1e-12);
        }
        // Continuous across the seam (in the operands' own spaces it would jump by a box's width).
        double[] a = shade(scene, PLACE, new Vec3(-1e-6, 0.3, -1)).rgb(), b = shade(scene, PLACE, new Vec3(1e-6, 0.3, -1)).rgb();
        assertEquals(a[0], b[0], 1e-5);
        assertEquals(a[1], b[1], 1e-5);
    }

    @Test
    void aSolidPatternOnADifferenceIsCarvedFromTheBlock() {
        Box body = half(0.3);
        Sphere cut = new Sphere(Vec3.ZERO, 0.8).transform(Transform.translate(0.3, 0, -1));
        Bool d = new Bool(Bool.Op.DIFFERENCE, List.of(body, cut));
        // Nested under a union that gives the material: the outermost material's block decides.
        Bool outer = new Bool(Bool.Op.UNION, List.of(d, half(5)));
        outer.material(textured(RECORD_POINT)).transform(PLACE);
        Scene scene = new SceneBuilder().add(outer).build();
        List<GObject> built = ((Bool) ((Bool) scene.objects().get(0)).operands().get(0)).operands();
        // The flat face of the box, and the hollow the sphere cut in it.
        for (Vec3 p : new Vec3[] {new Vec3(-0.15, 0.9, -1), new Vec3(0.75, -0.9, -1), new Vec3(0.3, 0, -1 + 0.8)}) {
            Shaded h = shade(scene, PLACE, p);
            assertSame(built.get(p.z() > -1 ? 1 : 0), h.object());
            assertRgb(new double[] {p.x(), p.y(), p.z()}, h.rgb(), p.toString());
        }
    }

    @Test
    void anOperandsOwnMaterialMapsInTheOperandsSpace() {
        Box left = half(-0.5), right = half(0.5);
        left.material(textured(RECORD_POINT));
        Bool union = new Bool(Bool.Op.UNION, List.of(left, right));
        union.transform(PLACE);
        Scene scene = new SceneBuilder().add(union).build();
        Vec3 p = new Vec3(-0.2, 0.3, -1);
        Shaded h = shade(scene, PLACE, p);
        assertSame(((Bool) scene.objects().get(0)).operands().get(0), h.object());
        // The left box's own space is the block's moved by +0.5 in x.
        assertRgb(new double[] {p.x() + 0.5, p.y(), p.z()}, h.rgb(), "operand's own space");
    }

    @Test
    void aMovingBlockMapsAtTheRaysTime() {
        Box left = half(-0.5), right = half(0.5);
        Bool union = new Bool(Bool.Op.UNION, List.of(left, right));
        union.material(textured(RECORD_POINT)).transform(PLACE).motion(Motion.linear(Vec3.Y, 2, 0, 1));
        Scene scene = new SceneBuilder().add(union).build();
        Transform atHalf = scene.objects().get(0).objectToWorld(0.5);
        Vec3 p = new Vec3(1e-6, -0.4, -1);
        Shaded h = shade(scene, atHalf, p, 0.5);
        assertSame(((Bool) scene.objects().get(0)).operands().get(1), h.object());
        assertRgb(new double[] {p.x(), p.y(), p.z()}, h.rgb(), "moving block");
    }
}
