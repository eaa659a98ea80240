package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import lt.spindulys.accel.BruteForce;
import lt.spindulys.accel.Bvh;
import lt.spindulys.accel.Octree;
import lt.spindulys.accel.WideBvh;
import org.junit.jupiter.api.Test;

/** The user's choice of acceleration structure: its names, and what each name builds. */
class AcceleratorKindTest {

    @Test
    void kindsAreNamedAsInSceneFiles() {
        for (AcceleratorKind k : AcceleratorKind.values()) assertEquals(k, AcceleratorKind.fromKeyword(k.keyword()));
        assertEquals(AcceleratorKind.BVH, AcceleratorKind.DEFAULT);
        var e = assertThrows(IllegalArgumentException.class, () -> AcceleratorKind.fromKeyword("kd"));
        assertEquals("unknown accelerator 'kd' (expected one of bvh, bvh-compact, bvh2, octree, bruteforce)", e.getMessage());
    }

    @Test
    void eachKindBuildsItsStructure() {
        TriangleMesh m = new TriangleMesh(TestMeshes.icosphere(3, 1));
        assertInstanceOf(Octree.class, AcceleratorKind.OCTREE.build(m));
        assertInstanceOf(Bvh.class, AcceleratorKind.BVH2.build(m));
        assertInstanceOf(BruteForce.class, AcceleratorKind.BRUTE_FORCE.build(m));
        assumeTrue(WideBvh.AVAILABLE, "this machine has no 256-bit vectors");
        assertInstanceOf(WideBvh.class, AcceleratorKind.BVH.build(m));
    }
}
