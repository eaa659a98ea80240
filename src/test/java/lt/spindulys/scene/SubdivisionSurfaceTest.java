package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.io.ObjReader;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivInput;

/** A subdivision surface is a closed (or open) triangle mesh like any other: hits, spans, normals, UVs. */
class SubdivisionSurfaceTest {
    static final String CUBE = TestMeshes.CUBE_OBJ;

    private static ControlMesh cube(String tags) {
        return ObjReader.parseSubdiv(CUBE + tags, "cube.obj").toControlMesh();
    }

    private static Vec3 randomDirection(Random rnd) {
        while (true) {
            Vec3 d = new Vec3(rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1);
            double l = d.length();
            if (l > 1e-3 && l <= 1) return d.times(1 / l);
        }
    }

    @Test
    void theRefinedCubeIsClosedAndMadeOfTwoTrianglesPerQuad() {
        SubdivisionSurface s = new SubdivisionSurface(cube(""), 2);
        assertTrue(s.isClosed());
        assertEquals(96, s.refined().faceCount());
        assertEquals(192, s.triangleCount());
        assertEquals(2, s.level());
        assertTrue(s.isSmooth());
        assertEquals("subdiv", s.kind());
    }

    @Test
    void holesAreLeftOutAndOpenTheSurface() {
        SubdivisionSurface s = frozen(new SubdivisionSurface(cube("t hole 1/0/0 1\n"), 2));
        assertFalse(s.isClosed());
        assertEquals(2 * (96 - 16), s.triangleCount());
        assertThrows(UnsupportedOperationException.class, () -> spans(s, ray(0, 0, -5, 0, 0, 1)));
        // The hole is the +z face (face 1): a ray down the z axis leaves through it unhindered.
        Ray r = ray(0, 0, 0, 0, 0, 1);
        assertNull(hit(s, r));
        assertNotNull(hit(s, ray(0, 0, 0, 0, 0, -1)));
    }

    @Test
    void raysFromInsideAlwaysHitAtLevel2() {
        Transform place = Transform.scale(2, 0.5, 1).then(Transform.rotate(new Vec3(1, 2, 3), 40)).then(Transform.translate(1, -2, 3));
        SubdivisionSurface plain = frozen(new SubdivisionSurface(cube(""), 2));
        SubdivisionSurface placed = frozen((SubdivisionSurface) new SubdivisionSurface(cube(""), 2).transform(place));
        Random rnd = new Random(17);
        TraceContext ctx = new TraceContext();
        Hit h = new Hit();
        int misses = 0;
        for (int i = 0; i < 20_000; i++) {
            // Inside: the refined cube contains the ball of radius 0.5 about the origin.
            Vec3 o = randomDirection(rnd).times(0.5 * rnd.nextDouble());
            Vec3 d = randomDirection(rnd);
            if (!plain.intersect(ray(o, d), h.reset(Double.POSITIVE_INFINITY), ctx)) misses++;
            Vec3 ow = place.point(o), dw = place.vector(d);
            if (!placed.intersect(ray(ow, dw), h.reset(Double.POSITIVE_INFINITY), ctx)) misses++;
        }
        assertEquals(0, misses);
    }

    @Test
    void spansGoThroughTheSurfaceAndAgreeWithTheNearestHit() {
        Material m = Material.builder().color(new lt.spindulys.math.Color(1, 0, 0)).build();
        SubdivisionSurface s = (SubdivisionSurface) new SubdivisionSurface(cube(""), 2).transform(Transform.rotateY(20)).material(m);
        TestBuild.freeze(s, Transform.IDENTITY, Material.DEFAULT, 0);
        Random rnd = new Random(5);
        TraceContext ctx = new TraceContext();
        SpanBuffer sp = new SpanBuffer();
        Hit h = new Hit(), end = new Hit();
        for (int i = 0; i < 2000; i++) {
            // From outside, through a point near the centre: one span.
            Vec3 target = randomDirection(rnd).times(0.3 * rnd.nextDouble());
            Vec3 o = randomDirection(rnd).times(5);
            Ray r = ray(o, target.minus(o).normalized());
            sp.clear();
            s.spans(r, sp, ctx);
            assertEquals(1, sp.size(), r.toString());
            assertTrue(sp.entry(0) < sp.exit(0));
            for (int e = 0; e < 2; e++) {
                sp.toHit(e, end);
                assertSame(s, end.object, "span ends name the surface, which the scene knows");
                assertSame(m, end.material);
                ShadingData sd = shade(s, r, end);
                Vec3 n = v(sd.ng);
                assertTrue(e == 0 ? n.dot(v(new double[] {r.dx, r.dy, r.dz})) < 0 : n.dot(v(new double[] {r.dx, r.dy, r.dz})) > 0,
                        "entry faces the ray, exit faces away");
            }
            assertTrue(s.intersect(r, h.reset(Double.POSITIVE_INFINITY), ctx));
            assertEquals(sp.entry(0), h.t, 1e-12);
            assertTrue(s.occluded(ray(o, target.minus(o).normalized()), ctx));
        }
        // Starting inside, the span begins behind the origin.
        Ray inside = ray(0, 0, 0, 1, 0, 0);
        sp.clear();
        s.spans(inside, sp, ctx);
        assertEquals(1, sp.size());
        assertTrue(sp.entry(0) < 0 && sp.exit(0) > 0);
    }

    @Test
    void occludedMatchesIntersect() {
        SubdivisionSurface s = frozen(new SubdivisionSurface(cube(""), 1));
        Random rnd = new Random(9);
        TraceContext ctx = new TraceContext();
        Hit h = new Hit();
        for (int i = 0; i < 3000; i++) {
            Vec3 o = randomDirection(rnd).times(3), d = randomDirection(rnd);
            Ray r = ray(o, d);
            r.tMax = 2 + rnd.nextDouble() * 3;
            assertEquals(s.intersect(r, h.reset(r.tMax), ctx), s.occluded(r, ctx), r.toString());
        }
    }

    @Test
    void smoothShadingInterpolatesLimitNormalsAndFlatShadingDoesNot() {
        SubdivisionSurface smooth = frozen(new SubdivisionSurface(cube(""), 2, true));
        SubdivisionSurface flat = frozen(new SubdivisionSurface(cube(""), 2, false));
        assertFalse(flat.isSmooth());
        double[] ln = smooth.refined().limitNormals();
        Random rnd = new Random(3);
        double maxDiff = 0;
        for (int i = 0; i < 200; i++) {
            Vec3 d = randomDirection(rnd);
            Ray r = ray(Vec3.ZERO, d);
            Hit h = hit(smooth, r);
            assertNotNull(h);
            ShadingData sd = shade(smooth, r, h);
            assertSane(sd);
            // The hit's triangle corners: its normal must be the blend of their limit normals.
            Vec3 expected = Vec3.ZERO;
            double[] w = {1 - h.u - h.v, h.u, h.v};
            int[] corners = cornersOf(smooth, r, h);
            for (int k = 0; k < 3; k++) expected = expected.plus(new Vec3(ln[3 * corners[k]], ln[3 * corners[k] + 1], ln[3 * corners[k] + 2]).times(w[k]));
            assertVec(expected.normalized(), sd.ns, 1e-9);

            Hit hf = hit(flat, ray(Vec3.ZERO, d));
            ShadingData f = shade(flat, ray(Vec3.ZERO, d), hf);
            assertVec(v(f.ng), f.ns, 1e-12);
            maxDiff = Math.max(maxDiff, v(sd.ns).minus(v(sd.ng)).length());
        }
        assertTrue(maxDiff > 1e-3, "smooth normals differ from the facets");
    }

    /**
     * Refined-vertex indices of the corners of the triangle hit: the surface's triangles built
     * again the same way (the frozen mesh has its own order), the one whose point at the hit's
     * barycentrics is the hit point.
     */
    private static int[] cornersOf(SubdivisionSurface s, Ray r, Hit h) {
        TriangleMesh m = new TriangleMesh(SubdivisionSurface.triangles(s.refined(), true));
        double[] p = m.data().positions();
        Vec3 target = new Vec3(r.pointX(h.t), r.pointY(h.t), r.pointZ(h.t));
        double w0 = 1 - h.u - h.v;
        for (int t = 0; t < m.triangleCount(); t++) {
            int a = 3 * m.triangleVertex(t, 0), b = 3 * m.triangleVertex(t, 1), c = 3 * m.triangleVertex(t, 2);
            Vec3 q = new Vec3(w0 * p[a] + h.u * p[b] + h.v * p[c], w0 * p[a + 1] + h.u * p[b + 1] + h.v * p[c + 1],
                    w0 * p[a + 2] + h.u * p[b + 2] + h.v * p[c + 2]);
            if (q.minus(target).length() < 1e-9) return new int[] {a / 3, b / 3, c / 3};
        }
        throw new AssertionError("no triangle of the surface holds the hit point " + target);
    }

    @Test
    void infinitelySharpCreasesStayCrispInShading() {
        String allEdges = "t crease 24/1/0 0 1 1 2 2 3 3 0 4 5 5 6 6 7 7 4 0 4 1 5 2 6 3 7 10\n";
        SubdivisionSurface s = frozen(new SubdivisionSurface(cube(allEdges), 3));
        Random rnd = new Random(11);
        for (int i = 0; i < 500; i++) {
            // Straight down onto the top face, right up to its sharp rim.
            double x = rnd.nextDouble() * 1.998 - 0.999, z = rnd.nextDouble() * 1.998 - 0.999;
            Ray r = ray(x, 5, z, 0, -1, 0);
            Hit h = hit(s, r);
            assertNotNull(h);
            assertEquals(4, h.t, 1e-12, "the top stays flat");
            assertVec(Vec3.Y, shade(s, r, h).ns, 1e-12);
        }
    }

    @Test
    void refinedUvsFromAnUnwrapReachTheHits() throws IOException {
        MeshData cube = WorkframeReader.readMesh(Path.of("scenes/models/cube.dat"));
        SubdivInput in = SubdivInput.of(cube).withCornerUvs(WorkframeReader.readUnwrap(Path.of("scenes/models/cube.tex"), cube));
        SubdivisionSurface s = frozen(new SubdivisionSurface(in.toControlMesh(), 2));
        // Face 1 of cube.dat is the +z face, cell (1, 0) of the 3 x 2 atlas.
        Ray r = ray(0.1, -0.2, 5, 0, 0, -1);
        ShadingData sd = shade(s, r, hit(s, r));
        assertTrue(sd.u > 1 / 3.0 && sd.u < 2 / 3.0 && sd.v > 0 && sd.v < 0.5, "uv " + sd.u + " " + sd.v);
    }

    @Test
    void levelsOutsideZeroToEightAreRefused() {
        ControlMesh c = cube("");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new SubdivisionSurface(c, 9));
        assertEquals("subdivision level must be between 0 and 8, found 9", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new SubdivisionSurface(c, -1));
        // The count rule alone (no heap per face); MAX_FACES itself needs gigabytes at the real figure.
        assertEquals(8, SubdivisionSurface.checkLevel(8, SubdivisionSurface.MAX_FACES, 0));
        e = assertThrows(IllegalArgumentException.class, () -> SubdivisionSurface.checkLevel(8, SubdivisionSurface.MAX_FACES + 1, 0));
        assertTrue(e.getMessage().startsWith("subdivision level 8 would make 16777217 faces"), e.getMessage());
    }

    @Test
    void levelZeroRendersTheControlMeshItself() {
        SubdivisionSurface s = frozen(new SubdivisionSurface(cube(""), 0, false));
        assertTrue(s.isClosed());
        assertEquals(12, s.triangleCount());
        Hit h = hit(s, ray(0.3, 0.2, -5, 0, 0, 1));
        assertEquals(4, h.t, 1e-12);
    }
}
