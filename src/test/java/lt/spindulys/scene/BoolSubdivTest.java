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

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;

/** CSG of subdivision surfaces: watertight differences and the refusal of open surfaces. */
class BoolSubdivTest {
    private static ControlMesh cube(int hole) {
        MeshData c = TestMeshes.cube();
        ControlMesh.Builder b = ControlMesh.builder(c.positions(), c.faceSizes(), c.vertexIndex());
        if (hole >= 0) b.hole(hole);
        return b.build();
    }

    /** Whether a point lies inside a closed leaf: the span of a ray from it that contains t = 0. */
    private static boolean inside(GObject o, double x, double y, double z, Random rnd, TraceContext ctx) {
        Ray r = new Ray().set(x, y, z, rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), 0, Double.POSITIVE_INFINITY);
        SpanBuffer b = new SpanBuffer();
        o.spans(r, b, ctx);
        for (int s = 0; s < b.size(); s++) if (b.entry(s) < 0 && b.exit(s) > 0) return true;
        return false;
    }

    @Test
    void raysFromInsideADifferenceOfSubdividedCubesAlwaysHit() {
        SubdivisionSurface a = new SubdivisionSurface(cube(-1), 3);
        SubdivisionSurface b = new SubdivisionSurface(cube(-1), 3);
        b.transform(Transform.scale(0.8, 0.8, 0.8)).transform(Transform.rotate(new Vec3(1, 1, 0), 30)).transform(Transform.translate(0.7, 0.3, 0.2));
        Bool d = new Bool(Bool.Op.DIFFERENCE, List.of(a, b));
        d.transform(Transform.rotateY(15));
        TestBuild.freeze(d, Transform.IDENTITY, Material.DEFAULT, 0);
        Random rnd = new Random(5);
        TraceContext ctx = new TraceContext();
        Hit hit = new Hit();
        ShadingData sd = new ShadingData();
        int removed = 0, inResult = 0;
        while (inResult < 3000) {
            double x = 2 * rnd.nextDouble() - 1, y = 2 * rnd.nextDouble() - 1, z = 2 * rnd.nextDouble() - 1;
            if (!inside(a, x, y, z, rnd, ctx)) continue;
            if (inside(b, x, y, z, rnd, ctx)) {
                // Cut away, so outside the result: the first boundary, if any, is an entry.
                removed++;
                Ray r = new Ray().set(x, y, z, rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), 0, Double.POSITIVE_INFINITY);
                hit.reset(r.tMax);
                if (d.intersect(r, hit, ctx)) {
                    hit.object.shade(r, hit, sd);
                    assertTrue(sd.ng[0] * r.dx + sd.ng[1] * r.dy + sd.ng[2] * r.dz < 0);
                }
                continue;
            }
            inResult++;
            Ray r = new Ray().set(x, y, z, rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), 0, Double.POSITIVE_INFINITY);
            hit.reset(r.tMax);
            assertTrue(d.intersect(r, hit, ctx), () -> "escaped from " + r);
            assertTrue(d.occluded(r, ctx));
            assertTrue(hit.object == a || hit.object == b && hit.flipNormal);
            // From inside the first boundary is an exit: the shaded normal points along the ray.
            hit.object.shade(r, hit, sd);
            assertTrue(sd.ng[0] * r.dx + sd.ng[1] * r.dy + sd.ng[2] * r.dz > 0);
        }
        assertTrue(removed > 300, "the second cube cuts a real piece out: " + removed);
    }

    @Test
    void openSubdivisionSurfaceIsRefused() {
        SubdivisionSurface open = new SubdivisionSurface(cube(2), 2);
        assertFalse(open.isClosed());
        assertEquals(4, open.boundaryEdgeCount()); // the four edges around the hole
        assertEquals(0, new SubdivisionSurface(cube(-1), 1).boundaryEdgeCount());
        open.name("lidless");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Bool(Bool.Op.DIFFERENCE, List.of(new Sphere(Vec3.ZERO, 1), open)));
        assertEquals("difference operand 2 (lidless) is not closed: it has 4 boundary edges", e.getMessage());
    }

    @Test
    void openMeshNamesItsBoundaryEdges() {
        // A cube with its top face missing: the four edges around the opening.
        MeshData c = TestMeshes.cube();
        int[] sizes = java.util.Arrays.copyOf(c.faceSizes(), 5);
        int[] idx = java.util.Arrays.copyOf(c.vertexIndex(), 20);
        TriangleMesh open = new TriangleMesh(new MeshData(c.positions(), null, null, sizes, idx, null, null, "box.obj"));
        assertFalse(open.isClosed());
        assertEquals(4, open.boundaryEdgeCount());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Bool(Bool.Op.INTERSECTION, List.of(new Sphere(Vec3.ZERO, 1), new Sphere(Vec3.X, 1), open)));
        assertEquals("intersection operand 3 (mesh) is not closed: it has 4 boundary edges", e.getMessage());
    }
}
