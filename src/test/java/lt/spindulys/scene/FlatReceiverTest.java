package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.trace.TraceContext;

/**
 * A flat object cannot shadow a point of itself, so shadow rays leaving it skip it
 * ({@link lt.spindulys.trace.TraceContext#shadowReceiver}): which objects count as flat, and that
 * the skip never changes the answer of {@link Scene#occluded}.
 */
class FlatReceiverTest {
    /** A tilted n x n grid of triangles in the plane through {@code o} spanned by u and v (two triangles per cell). */
    private static double[] tiltedGrid(int n, Vec3 o, Vec3 u, Vec3 v, double lift) {
        double[] c = new double[n * n * 18];
        int k = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double[][] corners = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}};
                for (double[] q : corners) {
                    Vec3 p = o.plus(u.times(q[0] / n)).plus(v.times(q[1] / n));
                    c[k++] = p.x(); c[k++] = p.y(); c[k++] = p.z();
                }
            }
        }
        c[c.length - 1] += lift; // the last corner off the plane, or not
        return c;
    }

    private static final Vec3 O = new Vec3(-3, -0.2, -3), U = new Vec3(6, 1.1, 0.3), V = new Vec3(0.2, 0.7, 6);

    @Test
    void planesTrianglesAndPlanarMeshesAreFlatOthersAreNot() {
        assertTrue(new Plane(new Vec3(0, 1, 0), 0).flat());
        assertTrue(new Triangle(new Vec3(0, 0, 0), new Vec3(1, 0, 0), new Vec3(0, 1, 1)).flat());
        assertTrue(new TriangleMesh(TestMeshes.soup(tiltedGrid(7, O, U, V, 0))).flat(), "a tilted planar grid");
        assertFalse(new TriangleMesh(TestMeshes.soup(tiltedGrid(7, O, U, V, 1e-6))).flat(), "one corner 1e-6 off the plane");
        assertFalse(new TriangleMesh(TestMeshes.cube()).flat());
        assertFalse(new TriangleMesh(TestMeshes.icosphere(1, 1)).flat());
        assertFalse(new Sphere(new Vec3(0, 0, 0), 1).flat());
        TriangleMesh ground = new TriangleMesh(TestMeshes.soup(tiltedGrid(2, O, U, V, 0)));
        assertTrue(ground.instance().flat(), "an instance of a flat mesh");
    }

    @Test
    void skippingTheFlatReceiverNeverChangesWhatBlocksItsShadowRays() {
        TriangleMesh ground = new TriangleMesh(TestMeshes.soup(tiltedGrid(9, O, U, V, 0)));
        ground.transform(Transform.rotateX(17).then(Transform.translate(0.1, 0.2, 0)));
        SceneBuilder b = new SceneBuilder().add(ground)
                .add(new Sphere(new Vec3(0.5, 2, 0.5), 0.6)).add(new Box(new Vec3(-2, 1.5, 1), new Vec3(-1, 2.5, 2)))
                .add(new TriangleMesh(TestMeshes.icosphere(2, 0.7)).transform(Transform.translate(1.5, 2.5, -1)));
        Scene scene = b.build();
        Transform world = Transform.rotateX(17).then(Transform.translate(0.1, 0.2, 0));
        Vec3 n = world.normal(U.cross(V)).normalized();
        Random r = new Random(77);
        Ray ray = new Ray();
        int blocked = 0, rays = 0;
        for (int i = 0; i < 20_000; i++) {
            Vec3 p = world.point(O.plus(U.times(r.nextDouble())).plus(V.times(r.nextDouble())));
            // Towards a random point on the normal's side, as the integrator's lights are.
            Vec3 target = new Vec3(8 * r.nextDouble() - 4, 3 + 3 * r.nextDouble(), 8 * r.nextDouble() - 4);
            Vec3 side = n.dot(target.minus(p)) >= 0 ? n : n.times(-1);
            if (side.dot(target.minus(p)) <= 1e-3) continue;
            Vec3 origin = p.plus(side.times(1e-9));
            ray.set(origin.x(), origin.y(), origin.z(), target.x() - origin.x(), target.y() - origin.y(), target.z() - origin.z(), 0, 1);
            TraceContext all = new TraceContext(), skipping = new TraceContext();
            skipping.shadowReceiver = ground;
            boolean full = scene.occluded(ray, all);
            assertEquals(full, scene.occluded(ray, skipping), "ray " + i + " from " + p);
            if (full) blocked++;
            rays++;
        }
        assertTrue(rays > 10_000 && blocked > 500 && blocked < rays - 500, blocked + " of " + rays + " rays blocked");
    }
}
