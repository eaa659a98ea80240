package lt.spindulys.accel;

import static lt.spindulys.accel.AcceleratorAgreementTest.mesh;
import static lt.spindulys.accel.BvhTest.concat;
import static lt.spindulys.accel.BvhTest.soup;

import java.util.Random;

import lt.spindulys.scene.AcceleratorKind;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Every real structure against brute force, 100,000 seeded rays per input, on the inputs that
 * break naive builds: everything in one plane, many identical triangles, tiny next to huge.
 */
class AcceleratorDegenerateInputTest {

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH2", "OCTREE"})
    void everythingInOnePlane(AcceleratorKind kind) {
        double[] c = soup(new Random(103), 150, 0.01, 0.15);
        for (int i = 2; i < c.length; i += 3) c[i] = 0.5;
        mesh(kind, c, 104);
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH2", "OCTREE"})
    void identicalTriangles(AcceleratorKind kind) {
        double[] one = {0.2, 0.2, 0.3, 0.8, 0.3, 0.5, 0.4, 0.9, 0.7};
        double[][] parts = new double[101][];
        for (int i = 0; i < 100; i++) parts[i] = one;
        parts[100] = soup(new Random(105), 50, 0.01, 0.1);
        mesh(kind, concat(parts), 106);
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH2", "OCTREE"})
    void tinyAndHugeTriangles(AcceleratorKind kind) {
        Random r = new Random(107);
        mesh(kind, concat(soup(r, 100, 1e-7, 1e-5), soup(r, 5, 10, 1000), soup(r, 50, 0.01, 0.1)), 108);
    }
}
