package lt.spindulys.math;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import org.junit.jupiter.api.Test;

class TransformTest {
    private static void assertVec(Vec3 e, Vec3 a, double tol) {
        assertEquals(0, e.minus(a).length(), tol, () -> "expected " + e + " but was " + a);
    }

    private static final Transform M = Transform.scale(2, 0.5, 3).then(Transform.rotate(new Vec3(1, 1, 0), 35))
            .then(Transform.translate(1, -2, 4));

    @Test void inverseUndoesTheTransform() {
        Transform inv = M.inverse();
        Random rnd = new Random(3);
        for (int i = 0; i < 100; i++) {
            Vec3 p = new Vec3(rnd.nextGaussian() * 5, rnd.nextGaussian() * 5, rnd.nextGaussian() * 5);
            assertVec(p, inv.point(M.point(p)), 1e-12);
            assertVec(p, M.point(inv.point(p)), 1e-12);
            assertVec(p, inv.vector(M.vector(p)), 1e-12);
        }
        assertVec(new Vec3(1, 2, 3), M.then(inv).point(new Vec3(1, 2, 3)), 1e-12);
    }

    @Test void thenComposesInWrittenOrder() {
        Transform moveThenTurn = Transform.translate(1, 0, 0).then(Transform.rotateZ(90));
        Transform turnThenMove = Transform.rotateZ(90).then(Transform.translate(1, 0, 0));
        assertVec(new Vec3(0, 1, 0), moveThenTurn.point(Vec3.ZERO), 1e-15);
        assertVec(new Vec3(1, 0, 0), turnThenMove.point(Vec3.ZERO), 1e-15);
        assertVec(new Vec3(1, 1, 0), turnThenMove.point(Vec3.X), 1e-15);
    }

    @Test void rotationsAreRightHanded() {
        assertVec(Vec3.Y, Transform.rotateZ(90).vector(Vec3.X), 1e-15);
        assertVec(Vec3.Z, Transform.rotateX(90).vector(Vec3.Y), 1e-15);
        assertVec(Vec3.X, Transform.rotateY(90).vector(Vec3.Z), 1e-15);
        assertVec(Transform.rotateZ(30).vector(Vec3.X), Transform.rotate(new Vec3(0, 0, 5), 30).vector(Vec3.X), 1e-15);
    }

    @Test void identityIsRecognisedAndNeutral() {
        assertTrue(Transform.IDENTITY.isIdentity());
        assertTrue(Transform.translate(0, 0, 0).isIdentity());
        assertFalse(Transform.translate(0, 0, 1e-300).isIdentity());
        assertSame(M, M.then(Transform.IDENTITY));
        assertSame(M, Transform.IDENTITY.then(M));
        assertEquals(Transform.scale(2, 2, 2), Transform.scale(2, 2, 2));
        assertEquals(Transform.scale(2, 2, 2).hashCode(), Transform.scale(2, 2, 2).hashCode());
    }

    @Test void normalsUnderNonUniformScaleStayPerpendicular() {
        Transform s = Transform.scale(2, 1, 1);
        // The plane x + y = 0 contains (1, -1, 0), which scales to (2, -1, 0).
        Vec3 n = s.normal(new Vec3(1, 1, 0));
        assertEquals(0, n.dot(s.vector(new Vec3(1, -1, 0))), 1e-15);
        assertVec(new Vec3(0.5, 1, 0), n, 1e-15);
        double[] buf = {9, 1, 1, 0};
        s.normalInPlace(buf, 1);
        assertEquals(9, buf[0]);
        assertVec(new Vec3(0.5, 1, 0).normalized(), new Vec3(buf[1], buf[2], buf[3]), 1e-15);
        // And in general: normal . tangent stays 0.
        Random rnd = new Random(5);
        for (int i = 0; i < 50; i++) {
            Vec3 a = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            Vec3 b = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            Vec3 nn = M.normal(a.cross(b));
            assertEquals(0, nn.dot(M.vector(a)), 1e-12);
            assertEquals(0, nn.dot(M.vector(b)), 1e-12);
        }
    }

    @Test void inPlaceHelpersMatchTheVectorForms() {
        double[] v = {1, 2, 3};
        M.vectorInPlace(v, 0);
        assertVec(M.vector(new Vec3(1, 2, 3)), new Vec3(v[0], v[1], v[2]), 1e-15);
        double[] local = new double[3];
        M.toLocalPoint(new double[] {1, 2, 3}, local);
        assertVec(M.inverse().point(new Vec3(1, 2, 3)), new Vec3(local[0], local[1], local[2]), 1e-12);
    }

    @Test void toLocalKeepsTheRayParameter() {
        Ray world = new Ray().set(1, 2, 3, -0.5, 2, 1, 0.25, 7);
        world.time = 0.5;
        Ray local = new Ray();
        M.toLocal(world, local);
        assertEquals(0.25, local.tMin);
        assertEquals(7, local.tMax);
        assertEquals(0.5, local.time);
        for (double t : new double[] {0, 1.5, -2, 10}) {
            Vec3 pw = new Vec3(world.pointX(t), world.pointY(t), world.pointZ(t));
            Vec3 pl = new Vec3(local.pointX(t), local.pointY(t), local.pointZ(t));
            assertVec(pw, M.point(pl), 1e-12);
        }
    }

    @Test void rejectsSingularAndInvalidMatrices() {
        assertThrows(IllegalArgumentException.class, () -> Transform.scale(1, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> Transform.translate(Double.NaN, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> Transform.ofMatrix(1, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> Transform.ofMatrix(1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0));
        Transform ok = Transform.ofMatrix(0, 1, 0, 5, 1, 0, 0, 0, 0, 0, 1, 0);
        assertVec(new Vec3(7, 1, 3), ok.point(new Vec3(1, 2, 3)), 0);
    }
}
