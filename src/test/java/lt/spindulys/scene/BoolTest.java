package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.assertVec;
import static lt.spindulys.scene.ShapeTestSupport.ray;
import static lt.spindulys.scene.ShapeTestSupport.v;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

/** Hand-checked cases of {@link Bool}: operations, normals, materials, bounds, ids, refusals. */
class BoolTest {
    private static final double EPS = 1e-9;

    private static Box box(double x0, double y0, double z0, double x1, double y1, double z1) {
        return new Box(new Vec3(x0, y0, z0), new Vec3(x1, y1, z1));
    }

    private static Bool bool(Bool.Op op, GObject... operands) { return new Bool(op, List.of(operands)); }

    private static <T extends GObject> T frozen(T o) {
        TestBuild.freeze(o, Transform.IDENTITY, Material.DEFAULT, 0);
        return o;
    }

    private static Hit hit(GObject o, Ray r) {
        Hit h = new Hit().reset(r.tMax);
        return o.intersect(r, h, new TraceContext()) ? h : null;
    }

    private static ShadingData shade(Ray r, Hit h) {
        ShadingData sd = new ShadingData();
        h.object.shade(r, h, sd);
        return sd;
    }

    @Test
    void keywords() {
        assertEquals("union", Bool.Op.UNION.keyword());
        assertEquals("intersection", Bool.Op.INTERSECTION.keyword());
        assertEquals("difference", Bool.Op.DIFFERENCE.keyword());
    }

    @Test
    void differenceOfBoxesShowsTheSubtractedFaceFlipped() {
        Box a = box(-1, -1, -1, 1, 1, 1), b = box(0, -2, -2, 2, 2, 2);
        Bool d = frozen(bool(Bool.Op.DIFFERENCE, a, b));
        // From +x: the cut face x = 0 belongs to b (its -x face), normal flipped to +x.
        Ray r = ray(5, 0.2, 0.3, -1, 0, 0);
        Hit h = hit(d, r);
        assertNotNull(h);
        assertEquals(5, h.t, EPS);
        assertSame(b, h.object);
        assertTrue(h.flipNormal);
        assertVec(Vec3.X, shade(r, h).ng, EPS);
        // From -x: a's own face.
        Ray l = ray(-5, 0.2, 0.3, 1, 0, 0);
        Hit hl = hit(d, l);
        assertEquals(4, hl.t, EPS);
        assertSame(a, hl.object);
        assertFalse(hl.flipNormal);
        assertVec(new Vec3(-1, 0, 0), shade(l, hl).ng, EPS);
        // Through the removed half only: nothing.
        assertNull(hit(d, ray(0.5, 5, 0, 0, -1, 0)));
        // Spans: [-1, 0] along x.
        SpanBuffer s = new SpanBuffer();
        d.spans(l, s, new TraceContext());
        assertEquals(1, s.size());
        assertEquals(4, s.entry(0), EPS);
        assertEquals(5, s.exit(0), EPS);
    }

    @Test
    void unionHasNoInnerSurfaces() {
        Sphere a = new Sphere(new Vec3(-0.5, 0, 0), 1), b = new Sphere(new Vec3(0.5, 0, 0), 1);
        Bool u = frozen(bool(Bool.Op.UNION, a, b));
        Ray r = ray(-5, 0, 0, 1, 0, 0);
        SpanBuffer s = new SpanBuffer();
        u.spans(r, s, new TraceContext());
        assertEquals(1, s.size());
        assertEquals(3.5, s.entry(0), EPS);
        assertEquals(6.5, s.exit(0), EPS);
        // From inside a (t = 0 at x = -0.5) the next surface is b's far side, not a's.
        Ray in = ray(-0.5, 0, 0, 1, 0, 0);
        Hit h = hit(u, in);
        assertSame(b, h.object);
        assertEquals(2, h.t, EPS);
    }

    @Test
    void intersectionOfSpheresIsTheLens() {
        Sphere a = new Sphere(new Vec3(-0.5, 0, 0), 1), b = new Sphere(new Vec3(0.5, 0, 0), 1);
        Bool i = frozen(bool(Bool.Op.INTERSECTION, a, b));
        Ray r = ray(-5, 0, 0, 1, 0, 0);
        Hit h = hit(i, r);
        assertSame(b, h.object); // b's near side at x = -0.5
        assertEquals(4.5, h.t, EPS);
        assertNull(hit(i, ray(-5, 0.95, 0, 1, 0, 0)));
    }

    @Test
    void rangeIsRespected() {
        Bool d = frozen(bool(Bool.Op.DIFFERENCE, box(-1, -1, -1, 1, 1, 1), box(-0.5, -0.5, -2, 0.5, 0.5, 2)));
        Ray r = ray(-5, 0, 0, 1, 0, 0);
        assertEquals(4, hit(d, r).t, EPS);
        r.tMin = 4.2; // inside the left wall: next is the hole's wall at x = -0.5
        assertEquals(4.5, hit(d, r).t, EPS);
        r.tMax = 4.4;
        assertNull(hit(d, r));
        assertFalse(d.occluded(r, new TraceContext()));
        r.tMax = 4.6;
        assertTrue(d.occluded(r, new TraceContext()));
    }

    @Test
    void spansKeepTrueEndpointsOutsideTheRange() {
        // Union of two overlapping boxes; a range starting inside the second only still reports
        // the span from the first box's entry.
        Bool u = frozen(bool(Bool.Op.UNION, box(-3, -1, -1, 0, 1, 1), box(-0.5, -1, -1, 2, 1, 1)));
        Ray r = ray(-5, 0, 0, 1, 0, 0);
        r.tMin = 4.8;
        SpanBuffer s = new SpanBuffer();
        u.spans(r, s, new TraceContext());
        assertEquals(1, s.size());
        assertEquals(2, s.entry(0), EPS);
        assertEquals(7, s.exit(0), EPS);
    }

    @Test
    void nestedBoolsAndTransforms() {
        // (box minus sphere) rotated and moved as a whole, inside a union with a sphere.
        Box a = box(-1, -1, -1, 1, 1, 1);
        Sphere hole = new Sphere(new Vec3(1, 0, 0), 0.5);
        Bool cut = bool(Bool.Op.DIFFERENCE, a, hole);
        cut.transform(Transform.rotateY(90)).transform(Transform.translate(10, 0, 0));
        Sphere far = new Sphere(new Vec3(20, 0, 0), 1);
        Bool u = frozen(bool(Bool.Op.UNION, cut, far));
        assertEquals(0, u.id());
        assertEquals(1, cut.id());
        assertEquals(2, a.id());
        assertEquals(3, hole.id());
        assertEquals(4, far.id());
        // rotateY(90) takes +x to -z: the dimple is now on the -z face of the box at x = 10.
        Ray r = ray(10, 0, -5, 0, 0, 1);
        Hit h = hit(u, r);
        assertSame(hole, h.object);
        assertEquals(4.5, h.t, EPS);
        assertTrue(h.flipNormal);
        assertVec(new Vec3(0, 0, -1), shade(r, h).ng, EPS); // bottom of the dimple faces the ray
        Ray side = ray(10, 0.9, -5, 0, 0, 1); // misses the dimple
        Hit hs = hit(u, side);
        assertSame(a, hs.object);
        assertEquals(4, hs.t, EPS);
        assertNotNull(hit(u, ray(25, 0, 0, -1, 0, 0)));
        assertEquals(4, hit(u, ray(25, 0, 0, -1, 0, 0)).t, EPS);
    }

    @Test
    void materialsOverride() {
        Material red = Material.builder().color(new Color(1, 0, 0)).build(), blue = Material.builder().color(new Color(0, 0, 1)).build();
        Material green = Material.builder().color(new Color(0, 1, 0)).build();
        Sphere a = new Sphere(new Vec3(-0.5, 0, 0), 1);
        a.material(red);
        Sphere b = new Sphere(new Vec3(0.5, 0, 0), 1);
        Bool plain = frozen(bool(Bool.Op.UNION, a, b));
        assertSame(red, hit(plain, ray(-5, 0, 0, 1, 0, 0)).material);
        assertSame(Material.DEFAULT, hit(plain, ray(5, 0, 0, -1, 0, 0)).material); // b inherits
        Sphere c = new Sphere(new Vec3(-0.5, 0, 0), 1);
        c.material(red);
        Sphere e = new Sphere(new Vec3(0.5, 0, 0), 1);
        e.material(blue);
        Bool inner = bool(Bool.Op.UNION, c, e);
        Bool outer = bool(Bool.Op.INTERSECTION, inner, box(-3, -3, -3, 3, 3, 3));
        outer.material(green);
        frozen(outer);
        Hit h = hit(outer, ray(-5, 0, 0, 1, 0, 0));
        assertSame(c, h.object);
        assertSame(green, h.material);
        ShadingData sd = shade(ray(-5, 0, 0, 1, 0, 0), h);
        assertSame(green, sd.material);
        int[] seen = {0};
        outer.forEachMaterial(m -> { seen[0]++; assertSame(green, m); });
        assertEquals(1, seen[0]);
    }

    @Test
    void boundsPerOperation() {
        Bounds ab = new Bounds(-1, -1, -1, 1, 1, 1), bb = new Bounds(0, 0, 0, 3, 3, 3);
        assertEquals(new Bounds(-1, -1, -1, 3, 3, 3), frozen(bool(Bool.Op.UNION, box(-1, -1, -1, 1, 1, 1), box(0, 0, 0, 3, 3, 3))).bounds());
        assertEquals(new Bounds(0, 0, 0, 1, 1, 1), frozen(bool(Bool.Op.INTERSECTION, box(-1, -1, -1, 1, 1, 1), box(0, 0, 0, 3, 3, 3))).bounds());
        assertEquals(ab, frozen(bool(Bool.Op.DIFFERENCE, box(-1, -1, -1, 1, 1, 1), box(0, 0, 0, 3, 3, 3))).bounds());
        Bool moved = bool(Bool.Op.DIFFERENCE, box(0, 0, 0, 3, 3, 3), box(-1, -1, -1, 1, 1, 1));
        moved.transform(Transform.translate(1, 0, 0));
        assertEquals(new Bounds(1, 0, 0, 4, 3, 3), moved.localBounds().transformed(moved.transform()));
        frozen(moved);
        assertEquals(new Bounds(1, 0, 0, 4, 3, 3), moved.bounds());
        assertEquals(bb, bb.intersection(bb));
        Bool apart = frozen(bool(Bool.Op.INTERSECTION, box(-1, -1, -1, 0, 0, 0), box(1, 1, 1, 2, 2, 2)));
        assertTrue(apart.bounds().isEmpty());
        assertNull(hit(apart, ray(-5, -0.5, -0.5, 1, 0, 0)));
    }

    @Test
    void refusals() {
        TriangleMesh open = new TriangleMesh(TestMeshes.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}));
        assertEquals(3, open.boundaryEdgeCount());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> bool(Bool.Op.UNION, new Sphere(Vec3.ZERO, 1), open.name("lid")));
        assertEquals("union operand 2 (lid) is not closed: it has 3 boundary edges", e.getMessage());
        Sphere s = new Sphere(Vec3.ZERO, 1);
        assertThrows(IllegalArgumentException.class, () -> new Bool(Bool.Op.UNION, List.of(s)));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> bool(Bool.Op.DIFFERENCE, s, s)).getMessage().contains("same object"));
        Sphere f = frozen(new Sphere(Vec3.ZERO, 1));
        assertEquals("intersection operand 2 (sphere) is an object of a built scene; give the object it was built from",
                assertThrows(IllegalArgumentException.class, () -> bool(Bool.Op.INTERSECTION, s, f)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Bool(Bool.Op.UNION, java.util.Arrays.asList(s, null)));
        assertEquals(0, new TriangleMesh(TestMeshes.cube()).boundaryEdgeCount());
        // An operand is not marked: it may be an operand of a second Bool (a scene freezes a copy per place).
        Sphere p = new Sphere(Vec3.ZERO, 1), q = new Sphere(Vec3.X, 1);
        Bool first = bool(Bool.Op.UNION, p, q);
        assertSame(q, bool(Bool.Op.DIFFERENCE, q, new Sphere(Vec3.Y, 1)).operands().get(0));
        assertSame(first, bool(Bool.Op.INTERSECTION, first, new Sphere(Vec3.Y, 1)).operands().get(0));
        assertSame(q, q.solid());
    }

    @Test
    void aTreeThatReusesItsOperandsIsCountedAsItExpands() {
        // Each level uses the previous Bool twice (through a second Bool), so the copies double per level.
        GObject t = bool(Bool.Op.UNION, new Sphere(Vec3.ZERO, 1), new Sphere(Vec3.X, 1));
        int levels = 0;
        IllegalArgumentException e = null;
        while (e == null && levels < 100) {
            GObject prev = t;
            try {
                t = bool(Bool.Op.UNION, prev, bool(Bool.Op.INTERSECTION, prev, new Sphere(Vec3.Y, 2)));
                levels++;
            } catch (IllegalArgumentException x) {
                e = x;
            }
        }
        assertNotNull(e, "refused before 100 levels");
        assertTrue(levels > 15 && levels < 30, levels + " levels");
        assertTrue(e.getMessage().startsWith("union operand 2 (intersection) brings the CSG tree to more than " + Bool.MAX_OBJECTS + " objects"), e.getMessage());
    }

    @Test
    void nestingIsLimited() {
        // MAX_NESTING levels build, and every object inside is marked with the outermost as its solid.
        Sphere leaf = new Sphere(Vec3.ZERO, 1);
        Bool chain = bool(Bool.Op.UNION, leaf, new Sphere(Vec3.X, 1));
        assertEquals(1, chain.nesting());
        for (int level = 2; level <= Bool.MAX_NESTING; level++) {
            chain = level % 2 == 0 ? bool(Bool.Op.INTERSECTION, new Sphere(Vec3.ZERO, 3), chain) : bool(Bool.Op.DIFFERENCE, chain, new Sphere(new Vec3(0, 5, 0), 1));
        }
        assertEquals(Bool.MAX_NESTING, chain.nesting());
        // One level more is refused, naming the operand (so the parser can locate it) and the limit.
        Bool deepest = chain;
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> bool(Bool.Op.UNION, new Sphere(Vec3.Y, 1), deepest));
        assertEquals("CSG nesting deeper than " + Bool.MAX_NESTING + " levels: union operand 2 (" + deepest.kind() + ") is " + Bool.MAX_NESTING
                + " levels deep (union and intersection take any number of operands, so a long chain can be one node)", e.getMessage());
        // The refusal leaves the tree free to be used.
        Scene scene = new SceneBuilder().add(chain).build();
        GObject built = scene.objects().get(0), builtLeaf = built;
        while (builtLeaf instanceof Bool b) builtLeaf = b.operands().get(b.op() == Bool.Op.INTERSECTION ? 1 : 0); // down the chain to leaf's copy
        assertSame(built, builtLeaf.solid());
        assertSame(built, ((Bool) built).operands().get(0).solid());
        assertSame(leaf, leaf.solid(), "the caller's objects are not marked");
        Hit h = new Hit();
        assertTrue(scene.intersect(ray(-5, 0, 0, 1, 0, 0), h, new TraceContext()));
        assertSame(builtLeaf, h.object);
        assertEquals(4, h.t, EPS);
    }

    @Test
    void meshOperandsWork() {
        TriangleMesh cube = new TriangleMesh(TestMeshes.cube()); // [-1, 1]^3
        Bool d = frozen(bool(Bool.Op.DIFFERENCE, cube, new Sphere(new Vec3(-1, 0, 0), 0.5)));
        Hit h = hit(d, ray(-5, 0, 0, 1, 0, 0));
        assertEquals(4.5, h.t, EPS);
        Hit m = hit(d, ray(-5, 0.8, 0, 1, 0, 0));
        assertSame(cube, m.object);
        assertEquals(4, m.t, EPS);
    }

    @Test
    void noMutableStaticState() {
        for (Field f : Bool.class.getDeclaredFields()) {
            if (Modifier.isStatic(f.getModifiers())) assertTrue(Modifier.isFinal(f.getModifiers()) && f.getType().isPrimitive(), f.getName());
        }
    }

    /** A nested tree with every operation, a mesh and a transform, for the context and thread tests. */
    private static Bool sample() {
        Bool inner = bool(Bool.Op.INTERSECTION, new Sphere(Vec3.ZERO, 1.2), box(-1, -1, -1, 1, 1, 1), new TriangleMesh(TestMeshes.icosphere(2, 1.3)));
        inner.transform(Transform.rotate(new Vec3(1, 2, 3), 25));
        Bool d = bool(Bool.Op.DIFFERENCE, inner, new Cylinder(new Vec3(0, -2, 0), new Vec3(0, 2, 0), 0.4), new Sphere(new Vec3(1, 1, 1), 0.6));
        return frozen(bool(Bool.Op.UNION, d, new Sphere(new Vec3(0, 0, 0.5), 0.3)));
    }

    @Test
    void borrowsAndReturnsTheContextScratch() {
        Bool u = sample();
        TraceContext ctx = new TraceContext();
        SpanBuffer first = ctx.acquireSpans();
        ctx.releaseSpans();
        ctx.stackTop = 3; // as if called from inside a traversal that owns three stack entries
        java.util.Random rnd = new java.util.Random(1);
        for (int i = 0; i < 500; i++) {
            Ray r = new Ray().set(3 * rnd.nextGaussian(), 3 * rnd.nextGaussian(), 3 * rnd.nextGaussian(),
                    rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), 0, Double.POSITIVE_INFINITY);
            u.intersect(r, new Hit().reset(r.tMax), ctx);
            u.occluded(r, ctx);
            u.spans(r, new SpanBuffer(), ctx);
        }
        assertEquals(3, ctx.stackTop);
        assertSame(first, ctx.acquireSpans(), "every borrowed span buffer was given back");
    }

    @Test
    void steadyStateQueriesAllocateNothing() {
        Bool u = sample();
        TraceContext ctx = new TraceContext();
        Ray r = new Ray();
        Hit h = new Hit();
        SpanBuffer out = new SpanBuffer();
        java.util.Random rnd = new java.util.Random(5);
        double[] dirs = new double[3 * 1024];
        for (int i = 0; i < dirs.length; i++) dirs[i] = rnd.nextGaussian();
        Runnable work = () -> {
            for (int i = 0; i < 10_000; i++) {
                int k = 3 * (i & 1023);
                r.set(0.1, 0.2, -0.1, dirs[k], dirs[k + 1], dirs[k + 2], 0, Double.POSITIVE_INFINITY);
                u.intersect(r, h.reset(r.tMax), ctx);
                u.occluded(r, ctx);
                out.clear();
                u.spans(r, out, ctx);
            }
        };
        long allocated = lt.spindulys.SteadyAllocation.least(work, 5, 4096);
        assertTrue(allocated < 4096, "30,000 queries allocated " + allocated + " bytes");
    }

    @Test
    void threadsSharingATreeSeeWhatOneThreadSees() throws Exception {
        Bool u = sample();
        int rays = 4000;
        double[] expected = new double[rays];
        TraceContext one = new TraceContext();
        for (int i = 0; i < rays; i++) expected[i] = trace(u, i, one);
        var pool = java.util.concurrent.Executors.newFixedThreadPool(4);
        try {
            List<java.util.concurrent.Future<Integer>> results = new java.util.ArrayList<>();
            for (int k = 0; k < 4; k++) {
                results.add(pool.submit(() -> {
                    TraceContext ctx = new TraceContext();
                    int agree = 0;
                    for (int i = 0; i < rays; i++) if (Double.compare(expected[i], trace(u, i, ctx)) == 0) agree++;
                    return agree;
                }));
            }
            for (var f : results) assertEquals(rays, f.get());
        } finally {
            pool.shutdown();
        }
        int hits = 0;
        for (double t : expected) if (t < Double.POSITIVE_INFINITY) hits++;
        assertTrue(hits > rays / 10 && hits < rays, "hits " + hits);
    }

    /** The hit distance of seeded ray {@code i} (infinity for a miss). */
    private static double trace(Bool b, int i, TraceContext ctx) {
        java.util.Random rnd = new java.util.Random(i);
        double ox = 3 * rnd.nextGaussian(), oy = 3 * rnd.nextGaussian(), oz = 3 * rnd.nextGaussian();
        // Aimed at the middle with some spread.
        Ray r = new Ray().set(ox, oy, oz, 0.5 * rnd.nextGaussian() - ox, 0.5 * rnd.nextGaussian() - oy, 0.5 * rnd.nextGaussian() - oz,
                0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        return b.intersect(r, h, ctx) ? h.t : Double.POSITIVE_INFINITY;
    }

    @Test
    void coincidentFacesGiveOneAnswerEverywhere() {
        // A box minus a box flush with its +x face, both placed by (different) transforms so the
        // shared plane's t differs by rounding from operand to operand.
        Box a = box(0, 0, 0, 1, 1, 1);
        a.transform(Transform.scale(2, 2, 2)).transform(Transform.translate(-1.3, -0.7, -1.1));
        Box b = box(0, 0, 0, 1, 1, 1);
        b.transform(Transform.translate(-0.3, -0.2, -0.4));
        // b spans x in [-0.3, 0.7] = a's +x face at 0.7: flush.
        Bool d = frozen(bool(Bool.Op.DIFFERENCE, a, b));
        TraceContext ctx = new TraceContext();
        int n = 0;
        for (int i = 0; i < 60; i++) {
            for (int j = 0; j < 60; j++) {
                double y = -0.15 + 0.5 * i / 59.0, z = -0.35 + 0.5 * j / 59.0; // inside b's y, z extent
                Ray r = new Ray().set(3, y, z, -1, 0.013, 0.007, 0, Double.POSITIVE_INFINITY);
                Hit h = new Hit().reset(r.tMax);
                assertTrue(d.intersect(r, h, ctx));
                // Always the bottom of the pocket (b's -x face, flipped), never a's +x face film.
                assertSame(b, h.object);
                assertEquals(0, h.prim); // b's -x face
                assertVec(Vec3.X, v(shadeN(r, h)), 1e-12);
                n++;
            }
        }
        assertEquals(3600, n);
    }

    @Test
    void coincidentFacesInUnionsAndIntersections() {
        // Two boxes meeting along the plane x = 0.7 (reached by different transforms).
        Box left = box(0, 0, 0, 1, 1, 1);
        left.transform(Transform.scale(2, 2, 2)).transform(Transform.translate(-1.3, -0.7, -1.1));
        Box right = box(-0.3, -0.2, -0.4, 0.7, 0.8, 0.6);
        right.transform(Transform.translate(1, 0, 0)); // x in [0.7, 1.7]
        Bool u = frozen(bool(Bool.Op.UNION, left, right));
        Box a = box(0, 0, 0, 1, 1, 1);
        a.transform(Transform.scale(2, 2, 2)).transform(Transform.translate(-1.3, -0.7, -1.1));
        Box flush = box(-0.3, -0.2, -0.4, 0.7, 0.8, 0.6); // shares a's +x face x = 0.7
        Bool i = frozen(bool(Bool.Op.INTERSECTION, a, flush));
        TraceContext ctx = new TraceContext();
        for (int y = 0; y < 40; y++) {
            for (int z = 0; z < 40; z++) {
                double py = -0.15 + 0.5 * y / 39.0, pz = -0.35 + 0.5 * z / 39.0;
                // Union: a ray from inside the left box along +x never stops at the shared face.
                Ray r = new Ray().set(0, py, pz, 1, 0.011, -0.009, 0, Double.POSITIVE_INFINITY);
                Hit h = new Hit().reset(r.tMax);
                assertTrue(u.intersect(r, h, ctx));
                assertSame(right, h.object);
                assertEquals(1, h.prim); // right's +x face
                // Intersection: from +x the shared face is the visible one, named by the first operand.
                Ray back = new Ray().set(3, py, pz, -1, 0.011, -0.009, 0, Double.POSITIVE_INFINITY);
                Hit hb = new Hit().reset(back.tMax);
                assertTrue(i.intersect(back, hb, ctx));
                assertSame(a, hb.object);
                assertEquals(1, hb.prim);
                assertEquals(2.3, hb.t, 1e-12);
            }
        }
    }

    @Test
    void aFlushCutThroughUnrelatedRotatedTransformsOpensTheFaceForEveryRay() {
        // The documented rule (class comment, scene-format.md "Coincident surfaces"): a difference
        // removes a face that a subtracted operand shares with the first, so a box minus a box
        // flush with one of its faces is open there. The operands here reach the shared plane
        // through unrelated, non-axis-aligned transforms, so the two operands' ray parameters on
        // it differ by rounding (not bit-identical, unlike the tests above); without the tie
        // tolerance about half of the rays into the pocket would stop on a film of a's face.
        Vec3 axis = new Vec3(1, 2, 3);
        // a: a unit cube about the origin, scaled to 2.3 x 1.7 x 2.9, turned 37 degrees, moved.
        // In its scaled (unrotated) frame its +x face is the plane x = 1.15, |y| <= 0.85, |z| <= 1.45.
        Box a = box(-0.5, -0.5, -0.5, 0.5, 0.5, 0.5);
        a.transform(Transform.scale(2.3, 1.7, 2.9)).transform(Transform.rotate(axis, 37)).transform(Transform.translate(0.1, -0.2, 0.3));
        // b: a corner-anchored unit cube scaled and moved to x in [0.8, 1.15], |y| <= 0.4,
        // |z| <= 0.6 of that frame (a pocket 0.35 deep whose +x face is a's), then turned in two
        // steps (20 + 17 degrees) and moved in two steps: the same placement, composed otherwise.
        Box b = box(0, 0, 0, 1, 1, 1);
        b.transform(Transform.scale(0.35, 0.8, 1.2)).transform(Transform.translate(0.8, -0.4, -0.6))
                .transform(Transform.rotate(axis, 20)).transform(Transform.rotate(axis, 17))
                .transform(Transform.translate(0.05, -0.1, 0.1)).transform(Transform.translate(0.05, -0.1, 0.2));
        Bool d = frozen(bool(Bool.Op.DIFFERENCE, a, b));
        // The face frame's placement, used only to aim the rays (a third composition).
        Transform place = Transform.rotate(axis, 37).then(Transform.translate(0.1, -0.2, 0.3));
        java.util.Random rnd = new java.util.Random(20261201L);
        TraceContext ctx = new TraceContext();
        int pocket = 0, face = 0;
        for (int i = 0; i < 20000; i++) {
            // A target on the face plane, and a ray arriving at it from the +x side (t = L there).
            double y = -0.6 + 1.2 * rnd.nextDouble(), z = -0.9 + 1.8 * rnd.nextDouble();
            double ux = 0.2 + rnd.nextDouble(), uy = rnd.nextGaussian() * 0.7, uz = rnd.nextGaussian() * 0.7;
            double len = 1 + 3 * rnd.nextDouble();
            boolean inPocket = Math.abs(y) < 0.4 && Math.abs(z) < 0.6;
            // Too close to the pocket's rim to say which side the ray crosses on: skipped.
            if (Math.abs(Math.abs(y) - 0.4) < 1e-6 || Math.abs(Math.abs(z) - 0.6) < 1e-6) continue;
            Vec3 target = place.point(new Vec3(1.15, y, z));
            Vec3 u = place.vector(new Vec3(ux, uy, uz));
            Vec3 o = target.plus(u.times(len));
            Ray r = new Ray().set(o.x(), o.y(), o.z(), -u.x(), -u.y(), -u.z(), 0, Double.POSITIVE_INFINITY);
            Hit h = new Hit().reset(r.tMax);
            String at = "ray " + i + " at face point y=" + y + " z=" + z;
            assertTrue(d.intersect(r, h, ctx), at);
            if (inPocket) {
                // Into the open pocket: the first surface is one of b's (bottom or wall, seen from
                // inside b, so flipped), never a's face film and never b's own +x face.
                assertSame(b, h.object, at);
                assertTrue(h.prim != 1, at);
                assertTrue(h.flipNormal, at);
                assertTrue(h.t > len, at);
                pocket++;
            } else {
                // Beside the pocket the face is still there, named by a.
                assertSame(a, h.object, at);
                assertEquals(1, h.prim, at); // a's +x face
                assertFalse(h.flipNormal, at);
                assertEquals(len, h.t, 1e-9 * len, at);
                face++;
            }
        }
        assertTrue(pocket > 7000 && face > 7000, pocket + " pocket rays, " + face + " face rays");
    }

    @Test
    void inASceneIdsAndTransparencyCoverTheOperands() {
        Material glass = Material.builder().kt(0.9).ior(1.5).build();
        Sphere a = new Sphere(Vec3.ZERO, 1), b = new Sphere(Vec3.X, 1);
        b.material(glass);
        Bool u = bool(Bool.Op.UNION, a, b);
        Sphere other = new Sphere(new Vec3(5, 0, 0), 1);
        Scene scene = new SceneBuilder().add(u).add(other).build();
        assertEquals(4, scene.objectIdCount());
        // The scene's own copies carry the ids; the caller's objects stay unfrozen.
        Bool fu = (Bool) scene.objects().get(0);
        GObject fa = fu.operands().get(0), fb = fu.operands().get(1), fo = scene.objects().get(1);
        assertEquals(List.of(0, 1, 2, 3), List.of(fu.id(), fa.id(), fb.id(), fo.id()));
        assertEquals(List.of(-1, -1, -1, -1), List.of(u.id(), a.id(), b.id(), other.id()));
        assertTrue(scene.hasTransparentObjects());
        assertSame(fu, fa.solid());
        assertSame(fu, fb.solid());
        assertSame(fu, fu.solid());
        assertSame(fo, fo.solid());
        Hit h = new Hit();
        assertTrue(scene.intersect(ray(-5, 0, 0, 1, 0, 0), h, new TraceContext()));
        assertSame(fa, h.object);
        assertEquals(4, h.t, EPS);
        // The same Bool overridden by an opaque material: no transparency left in the scene.
        Sphere c = new Sphere(Vec3.ZERO, 1), e = new Sphere(Vec3.X, 1);
        e.material(glass);
        Bool opaque = bool(Bool.Op.UNION, c, e);
        opaque.material(Material.DEFAULT);
        assertFalse(new SceneBuilder().add(opaque).build().hasTransparentObjects());
        // The scene's copies are frozen; the caller's Bool stays editable.
        assertThrows(IllegalStateException.class, () -> fu.material(glass));
        assertSame(u, u.material(glass));
    }

    private static double[] shadeN(Ray r, Hit h) { return shade(r, h).ng; }

    @Test
    void aNearerPlainHitFoundAfterAFlippedCsgHitIsNotFlipped() {
        // Tested in the order added (no structure): first the hollow's far wall (a subtracted,
        // flipped surface), then a small sphere inside the hollow, nearer, which must shade as an
        // ordinary sphere.
        Bool hollow = bool(Bool.Op.DIFFERENCE, new Box(new Vec3(-2, -2, -2), new Vec3(2, 2, 2)), new Sphere(Vec3.ZERO, 1.5));
        Sphere inside = new Sphere(new Vec3(0, 0, 0.5), 0.3);
        Scene scene = new SceneBuilder().settings(RenderSettings.builder().accelerator(lt.spindulys.scene.AcceleratorKind.BRUTE_FORCE).build())
                .add(hollow).add(inside).build();
        Ray r = new Ray().set(0, 0, -1, 0, 0, 1, 0, Double.POSITIVE_INFINITY);
        TraceContext ctx = new TraceContext();
        Hit h = new Hit();
        assertTrue(scene.objects().get(0).intersect(r, h.reset(r.tMax), ctx));
        assertTrue(h.flipNormal, "from inside the hollow its far wall is a subtracted surface");
        assertTrue(scene.intersect(r, h, ctx));
        assertSame(scene.objects().get(1), h.object);
        assertEquals(1.2, h.t, 1e-12);
        assertFalse(h.flipNormal);
        ShadingData sd = new ShadingData();
        h.object.shade(r, h, sd);
        assertTrue(sd.ns[2] < 0, "the sphere's normal faces the ray");
    }
}
