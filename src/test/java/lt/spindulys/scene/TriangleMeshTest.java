package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.io.ObjReader;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Uv;

class TriangleMeshTest {
    private static final double EPS = 1e-12;

    private static TriangleMesh frozen(TriangleMesh m) {
        TestBuild.freeze(m, Transform.IDENTITY, Material.DEFAULT, 0);
        return m;
    }

    /** Textured, so shading computes uv and derivatives (untextured hits may skip them). */
    private static final Material TEXTURED = Material.builder().name("textured")
            .texture(Channel.DIFFUSE, (p, rgb) -> { rgb[0] = rgb[1] = rgb[2] = 1; }, new Uv(1, 1)).build();

    private static TriangleMesh frozenTextured(TriangleMesh m) {
        TestBuild.freeze(m, Transform.IDENTITY, TEXTURED, 0);
        return m;
    }

    private static TriangleMesh obj(String text) {
        return new TriangleMesh(ObjReader.parse(text, "test.obj"));
    }

    /** A 2 x 1 quad in z = 0 with u = x / 2, v = y, facing +z. */
    private static final String QUAD = """
            v 0 0 0
            v 2 0 0
            v 2 1 0
            v 0 1 0
            vt 0 0
            vt 1 0
            vt 1 1
            vt 0 1
            f 1/1 2/2 3/3 4/4
            """;

    private static void assertVec(double x, double y, double z, double[] v) {
        assertEquals(x, v[0], EPS, "x");
        assertEquals(y, v[1], EPS, "y");
        assertEquals(z, v[2], EPS, "z");
    }

    @Test
    void hitAndShadeAKnownQuad() {
        TriangleMesh m = frozenTextured(obj(QUAD));
        assertEquals(2, m.triangleCount());
        assertEquals(new Bounds(0, 0, 0, 2, 1, 0), m.localBounds());
        assertFalse(m.isSmooth());
        Ray r = new Ray().set(1.5, 0.25, 3, 0, 0, -2, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        assertTrue(m.intersect(r, h, new TraceContext()));
        assertEquals(1.5, h.t, EPS);
        assertEquals(0, h.prim); // the fan's first triangle (1, 2, 3)
        assertEquals(0.5, h.u, EPS); // p = a + u (b - a) + v (c - a) = (2u + 2v, v)
        assertEquals(0.25, h.v, EPS);
        assertEquals(m, h.object);

        ShadingData sd = new ShadingData();
        m.shade(r, h, sd);
        assertVec(1.5, 0.25, 0, sd.p);
        assertVec(0, 0, 1, sd.ng);
        assertVec(0, 0, 1, sd.ns);
        assertEquals(0.75, sd.u, EPS);
        assertEquals(0.25, sd.v, EPS);
        assertVec(2, 0, 0, sd.dpdu);
        assertVec(0, 1, 0, sd.dpdv);

        // The second triangle, hit from behind: the normal still points out of the front side.
        r.set(0.5, 0.75, -1, 0, 0, 1, 0, Double.POSITIVE_INFINITY);
        h.reset(r.tMax);
        assertTrue(m.intersect(r, h, new TraceContext()));
        assertEquals(1, h.prim);
        m.shade(r, h, sd);
        assertVec(0, 0, 1, sd.ng);
        assertEquals(0.25, sd.u, EPS);
        assertEquals(0.75, sd.v, EPS);
        assertVec(2, 0, 0, sd.dpdu);

        // Outside the quad, and beyond tMax: no hit.
        assertFalse(m.intersect(r.set(2.5, 0.5, 1, 0, 0, -1, 0, 10), h.reset(10), new TraceContext()));
        assertFalse(m.intersect(r.set(1, 0.5, 1, 0, 0, -1, 0, 0.999), h.reset(0.999), new TraceContext()));
        assertTrue(m.occluded(r.set(1, 0.5, 1, 0, 0, -1, 0, 1.001), new TraceContext()));
        assertFalse(m.occluded(r.set(1, 0.5, 1, 0, 0, -1, 0, 0.999), new TraceContext()));
    }

    @Test
    void anUntexturedHitGetsItsPointAndNormalsButNoParameters() {
        TriangleMesh m = frozen(obj(QUAD));
        Ray r = new Ray().set(1.5, 0.25, 3, 0, 0, -2, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        assertTrue(m.intersect(r, h, new TraceContext()));
        ShadingData sd = new ShadingData();
        sd.u = sd.v = -7; // left as they were: the uv arrays are not read
        m.shade(r, h, sd);
        assertFalse(sd.needsParameters);
        assertVec(1.5, 0.25, 0, sd.p);
        assertVec(0, 0, 1, sd.ng);
        assertVec(0, 0, 1, sd.ns);
        assertEquals(-7, sd.u);
        assertEquals(-7, sd.v);
    }

    @Test
    void withoutTextureCoordinatesUvAreTheBarycentricsAndDerivativesTheEdges() {
        TriangleMesh m = frozenTextured(obj("v 0 0 0\nv 2 0 0\nv 0 3 0\nf 1 2 3\n"));
        Ray r = new Ray().set(0.5, 1.5, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        assertTrue(m.intersect(r, h, new TraceContext()));
        ShadingData sd = new ShadingData();
        m.shade(r, h, sd);
        assertEquals(0.25, sd.u, EPS);
        assertEquals(0.5, sd.v, EPS);
        assertVec(2, 0, 0, sd.dpdu);
        assertVec(0, 3, 0, sd.dpdv);
    }

    @Test
    void transformedMeshHitsInWorldSpace() {
        TriangleMesh m = obj(QUAD);
        m.transform(Transform.rotateX(90).then(Transform.translate(0, 0, 5)));
        frozen(m);
        // After rotating +z onto -y... the quad lies in y = 0, z in [5, 6].
        Ray r = new Ray().set(1, 3, 5.5, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        assertTrue(m.intersect(r, h, new TraceContext()));
        assertEquals(3, h.t, EPS);
        ShadingData sd = new ShadingData();
        m.shade(r, h, sd);
        assertVec(1, 0, 5.5, sd.p);
        assertVec(0, -1, 0, sd.ng);
    }

    /** A tilted-normal quad: normals lean outwards along x at the left and right edges. */
    private static final String TILTED = """
            v 0 0 0
            v 2 0 0
            v 2 1 0
            v 0 1 0
            vn -1 0 1
            vn 1 0 1
            f 1//1 2//2 3//2 4//1
            """;

    @Test
    void smoothInterpolatesFileNormalsFlatUsesTheGeometricNormal() {
        TriangleMesh smooth = frozen(obj(TILTED));
        assertTrue(smooth.isSmooth(), "smooth by default when the file has normals");
        Ray r = new Ray().set(1.5, 0.25, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        ShadingData sd = new ShadingData();
        assertTrue(smooth.intersect(r, h, new TraceContext()));
        smooth.shade(r, h, sd);
        // At x = 1.5 the weights are 1/4 left, 3/4 right: n = (0.5, 0, 1) normalised.
        double l = Math.sqrt(1.25);
        assertVec(0.5 / l, 0, 1 / l, sd.ns);
        assertVec(0, 0, 1, sd.ng);

        TriangleMesh flat = frozen(obj(TILTED).smooth(false));
        h.reset(r.tMax);
        assertTrue(flat.intersect(r, h, new TraceContext()));
        flat.shade(r, h, sd);
        assertVec(0, 0, 1, sd.ns);
        assertVec(0, 0, 1, sd.ng);
    }

    @Test
    void shadingNormalIsFlippedOntoTheGeometricSide() {
        // Normals pointing against the winding (into -z).
        TriangleMesh m = frozen(obj(TILTED.replace("vn -1 0 1", "vn -1 0 -1").replace("vn 1 0 1", "vn 1 0 -1")));
        Ray r = new Ray().set(1.5, 0.25, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        ShadingData sd = new ShadingData();
        assertTrue(m.intersect(r, h, new TraceContext()));
        m.shade(r, h, sd);
        double l = Math.sqrt(1.25);
        assertVec(-0.5 / l, 0, 1 / l, sd.ns);
        assertVec(0, 0, 1, sd.ng);
    }


    @Test
    void smoothWithoutFileNormalsUsesAreaWeightedVertexNormals() {
        TriangleMesh flat = frozen(obj(TestMeshes.OCTAHEDRON_OBJ));
        assertFalse(flat.isSmooth(), "flat by default without normals");
        assertTrue(flat.isClosed());
        TriangleMesh smooth = frozen(obj(TestMeshes.OCTAHEDRON_OBJ).smooth(true));
        TraceContext ctx = new TraceContext();
        ShadingData sd = new ShadingData();
        double s = 1 / Math.sqrt(3);
        // Close to the apex (0, 0, 1) the symmetric vertex normal there, (0, 0, 1), dominates.
        Ray r = new Ray().set(1e-9, 2e-9, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit().reset(r.tMax);
        assertTrue(smooth.intersect(r, h, ctx));
        smooth.shade(r, h, sd);
        assertVec(s, s, s, sd.ng);
        assertVec(0, 0, 1, new double[] {Math.round(sd.ns[0] * 1e6) / 1e6, Math.round(sd.ns[1] * 1e6) / 1e6, Math.round(sd.ns[2] * 1e6) / 1e6});
        // At a face centre the three axis normals average to the face normal.
        r.set(0, 0, 0, 1, 1, 1, 0, Double.POSITIVE_INFINITY);
        h.reset(r.tMax);
        assertTrue(smooth.intersect(r, h, ctx));
        smooth.shade(r, h, sd);
        assertVec(s, s, s, sd.ns);
        h.reset(Double.POSITIVE_INFINITY);
        r.set(1e-9, 2e-9, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        assertTrue(flat.intersect(r, h, ctx));
        flat.shade(r, h, sd);
        assertVec(s, s, s, sd.ns);
    }

    @Test
    void closedAndOpenMeshes() {
        assertTrue(new TriangleMesh(TestMeshes.cube()).isClosed());
        assertTrue(new TriangleMesh(TestMeshes.gridCube(5)).isClosed());
        assertTrue(new TriangleMesh(TestMeshes.icosphere(2, 1)).isClosed());
        assertTrue(new TriangleMesh(TestMeshes.splitCube()).isClosed(), "repeated positions count as one vertex");
        assertFalse(obj(QUAD).isClosed());
        assertFalse(obj("").isClosed(), "no triangles bound nothing");
        // The cube without its last face.
        MeshData c = TestMeshes.cube();
        MeshData open = new MeshData(c.positions(), null, null, java.util.Arrays.copyOf(c.faceSizes(), 5),
                java.util.Arrays.copyOf(c.vertexIndex(), 20), null, null, "open");
        assertFalse(new TriangleMesh(open).isClosed());
        // Two tetrahedra sharing an edge: that edge has four triangles.
        TriangleMesh twoTets = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 0 -1\nv 1 1 0\n"
                + "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"
                + "f 1 2 5\nf 2 6 5\nf 6 1 5\nf 1 6 2\n");
        assertFalse(twoTets.isClosed());
    }

    @Test
    void degenerateTrianglesAreDroppedAndCounted() {
        TriangleMesh m = obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n"
                + "f 1 2 3\n" // collinear
                + "f 1 1 4\n" // repeated vertex
                + "f 1 2 4 3\n"); // fan: (1 2 4) is fine, (1 4 3) too
        assertEquals(2, m.triangleCount());
        assertEquals(2, m.degenerateCount());
        assertThrows(IllegalArgumentException.class,
                () -> new TriangleMesh(new MeshData(new double[] {0, 0, 0}, null, null, new int[] {3}, new int[] {0, 0, 1}, null, null, "x")));
    }

    // ---- spans ----

    private static SpanBuffer spans(TriangleMesh m, double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax) {
        SpanBuffer out = new SpanBuffer();
        m.spans(new Ray().set(ox, oy, oz, dx, dy, dz, tMin, tMax), out, new TraceContext());
        return out;
    }

    private static void assertSpans(SpanBuffer s, double... ends) {
        assertEquals(ends.length / 2, s.size(), "number of spans");
        for (int i = 0; i < ends.length / 2; i++) {
            assertEquals(ends[2 * i], s.entry(i), 1e-12, "entry " + i);
            assertEquals(ends[2 * i + 1], s.exit(i), 1e-12, "exit " + i);
        }
    }

    @Test
    void spansOfAClosedCube() {
        TriangleMesh cube = frozen(new TriangleMesh(TestMeshes.cube()));
        double inf = Double.POSITIVE_INFINITY;
        assertSpans(spans(cube, -5, 0.3, 0.2, 1, 0, 0, 0, inf), 4, 6);
        // Origin inside: the true entry lies behind the origin.
        assertSpans(spans(cube, 0.1, 0.2, 0.3, 2, 0, 0, 0, inf), -0.55, 0.45);
        // Through an edge of two faces, and through a corner of three (several triangles each).
        assertSpans(spans(cube, -5, -5, 0.3, 1, 1, 0, 0, inf), 4, 6);
        assertSpans(spans(cube, -5, -5, -5, 1, 1, 1, 0, inf), 4, 6);
        assertSpans(spans(cube, 0, 0, 0, 1, 1, 1, 0, inf), -1, 1);
        // Along the diagonal of a face quad (the edge between its two triangles).
        assertSpans(spans(cube, 0.25, 0.25, 5, 0, 0, -1, 0, inf), 4, 6);
        // Grazing an edge, or touching a corner, from outside: nothing inside.
        assertSpans(spans(cube, 0, 2, 0.3, 1, -1, 0, 0, inf));
        assertSpans(spans(cube, 0, 2, 1, 1, -1, 0, 0, inf));
        assertSpans(spans(cube, -1, 3, 0, 1, -1, 0.5, 0, inf));
        // Only spans overlapping (tMin, tMax) are reported, with their true ends.
        assertSpans(spans(cube, -5, 0.3, 0.2, 1, 0, 0, 0, 3));
        assertSpans(spans(cube, -5, 0.3, 0.2, 1, 0, 0, 0, 5), 4, 6);
        assertSpans(spans(cube, -5, 0.3, 0.2, 1, 0, 0, 5.5, 7), 4, 6);
        assertSpans(spans(cube, -5, 0.3, 0.2, 1, 0, 0, 6, 7));
        assertSpans(spans(cube, 5, 0.3, 0.2, 1, 0, 0, 0, inf));
        // Missing entirely.
        assertSpans(spans(cube, -5, 1.5, 0.2, 1, 0, 0, 0, inf));
    }

    @Test
    void spanEndpointsShadeLikeHits() {
        TriangleMesh cube = frozen(new TriangleMesh(TestMeshes.cube()));
        Ray r = new Ray().set(-5, 0.3, 0.2, 1, 0, 0, 0, Double.POSITIVE_INFINITY);
        SpanBuffer out = new SpanBuffer();
        cube.spans(r, out, new TraceContext());
        Hit h = new Hit();
        ShadingData sd = new ShadingData();
        out.toHit(0, h);
        cube.shade(r, h, sd);
        assertVec(-1, 0.3, 0.2, sd.p);
        assertVec(-1, 0, 0, sd.ng);
        out.toHit(1, h);
        cube.shade(r, h, sd);
        assertVec(1, 0.3, 0.2, sd.p);
        assertVec(1, 0, 0, sd.ng);
    }

    @Test
    void spansOfSeveralComponentsAndTransformedMeshes() {
        // Two disjoint cubes, and two overlapping cubes (counted crossings merge them).
        MeshData c = TestMeshes.cube();
        TriangleMesh two = frozen(new TriangleMesh(twoCubes(c, 3)));
        assertSpans(spans(two, -5, 0.5, 0.5, 1, 0, 0, 0, Double.POSITIVE_INFINITY), 4, 6, 7, 9);
        TriangleMesh overlapping = frozen(new TriangleMesh(twoCubes(c, 1)));
        assertTrue(overlapping.isClosed());
        assertSpans(spans(overlapping, -5, 0.5, 0.5, 1, 0, 0, 0, Double.POSITIVE_INFINITY), 4, 7);

        TriangleMesh moved = new TriangleMesh(c);
        moved.transform(Transform.scale(2, 1, 1).then(Transform.translate(10, 0, 0)));
        frozen(moved);
        assertSpans(spans(moved, 0, 0, 0, 1, 0, 0, 0, Double.POSITIVE_INFINITY), 8, 12);
    }

    private static MeshData twoCubes(MeshData c, double shift) {
        double[] p = new double[2 * c.positions().length];
        System.arraycopy(c.positions(), 0, p, 0, c.positions().length);
        for (int i = 0; i < c.positions().length; i++) p[c.positions().length + i] = c.positions()[i] + (i % 3 == 0 ? shift : 0);
        int[] vi = new int[2 * c.vertexIndex().length];
        for (int i = 0; i < c.vertexIndex().length; i++) {
            vi[i] = c.vertexIndex()[i];
            vi[c.vertexIndex().length + i] = c.vertexIndex()[i] + c.vertexCount();
        }
        int[] sizes = new int[2 * c.faceCount()];
        java.util.Arrays.fill(sizes, 4);
        return new MeshData(p, null, null, sizes, vi, null, null, "two cubes");
    }

    @Test
    void spansOfASphereAgreeWithNearestHits() {
        TriangleMesh sphere = frozen(new TriangleMesh(TestMeshes.icosphere(3, 1)));
        double[] p = sphere.data().positions();
        Random rnd = new Random(11);
        TraceContext ctx = new TraceContext();
        SpanBuffer out = new SpanBuffer();
        Ray r = new Ray();
        Hit h = new Hit();
        int aimed = 0, touches = 0;
        for (int i = 0; i < 20_000; i++) {
            double ox = rnd.nextGaussian() * 3, oy = rnd.nextGaussian() * 3, oz = rnd.nextGaussian() * 3;
            double o2 = ox * ox + oy * oy + oz * oz;
            if (o2 > 0.8 && o2 < 1.1) continue; // near the surface: neither clearly inside nor outside
            double dx, dy, dz;
            if (i % 2 == 0) {
                // Aim at a vertex, or at the midpoint of one of a triangle's edges.
                int t = rnd.nextInt(sphere.triangleCount()), a = 3 * sphere.triangleVertex(t, 0), b = 3 * sphere.triangleVertex(t, 1);
                double f = i % 4 == 0 ? 0 : 0.5;
                dx = p[a] + f * (p[b] - p[a]) - ox; dy = p[a + 1] + f * (p[b + 1] - p[a + 1]) - oy; dz = p[a + 2] + f * (p[b + 2] - p[a + 2]) - oz;
                aimed++;
            } else {
                dx = rnd.nextGaussian(); dy = rnd.nextGaussian(); dz = rnd.nextGaussian();
            }
            r.set(ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
            out.clear();
            sphere.spans(r, out, ctx);
            boolean inside = o2 < 0.8;
            h.reset(r.tMax);
            boolean hit = sphere.intersect(r, h, ctx);
            if (inside) {
                assertTrue(hit);
                assertEquals(1, out.size(), "a convex solid has one span");
                assertTrue(out.entry(0) < 0);
                assertEquals(h.t, out.exit(0), 1e-9 * h.t);
            } else if (hit && out.size() == 1) {
                assertEquals(h.t, out.entry(0), 1e-9 * h.t);
                double mid = 0.5 * (out.entry(0) + out.exit(0));
                // (A near-touch can leave a sliver of a span too thin to test against the planes.)
                assertTrue(out.exit(0) - out.entry(0) < 1e-9 || insideConvex(sphere, r.pointX(mid), r.pointY(mid), r.pointZ(mid)), "ray " + r);
            } else if (hit) {
                // A line that only touches the surface (at a silhouette vertex or edge) encloses nothing.
                assertEquals(0, out.size(), "ray " + r);
                double e = 1e-7 * h.t;
                assertFalse(insideConvex(sphere, r.pointX(h.t + e), r.pointY(h.t + e), r.pointZ(h.t + e)), "ray " + r);
                assertFalse(insideConvex(sphere, r.pointX(h.t - e), r.pointY(h.t - e), r.pointZ(h.t - e)), "ray " + r);
                touches++;
            } else {
                assertTrue(out.size() == 0 || out.entry(0) < 0 && out.exit(0) <= 1e-9, "spans behind the origin only");
            }
        }
        assertTrue(aimed > 0);
        assertTrue(touches < aimed / 5, "touching only happens at the silhouette: " + touches + " of " + aimed);
    }

    /** Strictly inside every face plane of a convex mesh. */
    private static boolean insideConvex(TriangleMesh m, double x, double y, double z) {
        double[] p = m.data().positions();
        for (int t = 0; t < m.triangleCount(); t++) {
            int a = 3 * m.triangleVertex(t, 0), b = 3 * m.triangleVertex(t, 1), c = 3 * m.triangleVertex(t, 2);
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
            double vx = p[c] - p[a], vy = p[c + 1] - p[a + 1], vz = p[c + 2] - p[a + 2];
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            if (nx * (x - p[a]) + ny * (y - p[a + 1]) + nz * (z - p[a + 2]) >= 0) return false;
        }
        return true;
    }

    @Test
    void steadyStateQueriesAllocateNothing() {
        TriangleMesh m = new TriangleMesh(TestMeshes.icosphere(3, 1));
        m.transform(Transform.translate(0.1, 0.2, 0.3));
        frozen(m);
        TraceContext ctx = new TraceContext();
        Ray r = new Ray();
        Hit h = new Hit();
        SpanBuffer out = new SpanBuffer();
        Random rnd = new Random(5);
        double[] dirs = new double[3 * 1024];
        for (int i = 0; i < dirs.length; i++) dirs[i] = rnd.nextGaussian();
        Runnable work = () -> {
            for (int i = 0; i < 20_000; i++) {
                int k = 3 * (i & 1023);
                r.set(0, 0, 0, dirs[k], dirs[k + 1], dirs[k + 2], 0, Double.POSITIVE_INFINITY);
                m.intersect(r, h.reset(r.tMax), ctx);
                m.occluded(r, ctx);
                out.clear();
                m.spans(r, out, ctx);
            }
        };
        long allocated = lt.spindulys.SteadyAllocation.least(work, 5, 4096);
        assertTrue(allocated < 4096, "60,000 queries allocated " + allocated + " bytes");
    }

    @Test
    void spansRequireAClosedMesh() {
        TriangleMesh quad = frozen(obj(QUAD));
        assertThrows(UnsupportedOperationException.class, () -> spans(quad, 0, 0, 1, 0, 0, -1, 0, 1));
    }

    @Test
    void smoothCannotChangeOnceFrozen() {
        TriangleMesh m = frozen(obj(QUAD));
        assertThrows(IllegalStateException.class, () -> m.smooth(true));
    }

    /** The three corner positions of triangle t, as written in the mesh's current order. */
    private static String corners(TriangleMesh m, int t) {
        double[] p = m.data().positions();
        StringBuilder sb = new StringBuilder();
        for (int c = 0; c < 3; c++) {
            int v = 3 * m.triangleVertex(t, c);
            sb.append(p[v]).append(' ').append(p[v + 1]).append(' ').append(p[v + 2]).append(';');
        }
        return sb.toString();
    }

    @Test
    void bvhLeafOrderKeepsEveryTriangleAndEveryHit() {
        MeshData d = TestMeshes.icosphere(3, 1);
        TriangleMesh reordered = new TriangleMesh(d), plain = new TriangleMesh(d);
        TestBuild.freeze(reordered, Transform.IDENTITY, Material.DEFAULT, 0, AcceleratorKind.BVH);
        TestBuild.freeze(plain, Transform.IDENTITY, Material.DEFAULT, 0, AcceleratorKind.BRUTE_FORCE);
        java.util.List<String> a = new java.util.ArrayList<>(), b = new java.util.ArrayList<>();
        for (int t = 0; t < plain.triangleCount(); t++) {
            a.add(corners(reordered, t));
            b.add(corners(plain, t));
        }
        assertFalse(a.equals(b), "the BVH put the triangles in its leaf order");
        java.util.Collections.sort(a);
        java.util.Collections.sort(b);
        assertEquals(b, a, "same triangles, same winding");
        assertEquals(d.positions().length, reordered.data().positions().length);
        // The source positions are shared with `plain`: reordering must not have touched them.
        assertEquals(corners(plain, 0), corners(new TriangleMesh(d), 0));

        Random rnd = new Random(5);
        TraceContext ctx = new TraceContext();
        Hit hr = new Hit(), hp = new Hit();
        for (int i = 0; i < 2_000; i++) {
            Ray r = new Ray().set(rnd.nextGaussian() * 2, rnd.nextGaussian() * 2, rnd.nextGaussian() * 2,
                    rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), 0, Double.POSITIVE_INFINITY);
            boolean x = reordered.intersect(r, hr.reset(r.tMax), ctx), y = plain.intersect(r, hp.reset(r.tMax), ctx);
            assertEquals(y, x);
            if (x) {
                assertEquals(hp.t, hr.t);
                assertEquals(corners(plain, hp.prim), corners(reordered, hr.prim));
                assertEquals(hp.u, hr.u);
                assertEquals(hp.v, hr.v);
            }
        }
    }
}
