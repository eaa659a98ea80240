package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.Supplier;

import org.junit.jupiter.api.Test;

/** Validation of control meshes, and the unusual topology OpenSubdiv accepts. */
class ControlMeshTest {
    /** Two quads sharing an edge: vertices 0..5. */
    static final double[] P = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
    static final int[] SIZES = {4, 4};
    static final int[] FV = {0, 1, 4, 3, 1, 2, 5, 4};

    static void fails(String expected, Supplier<ControlMesh> build) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, build::get);
        assertTrue(e.getMessage().contains(expected), () -> "message '" + e.getMessage() + "' should contain '" + expected + "'");
    }

    @Test
    void aLoopMeshNeedsTrianglesAndCatmullClarkNeedsItsScheme() {
        SubdivOptions loop = SubdivOptions.DEFAULT.withScheme(SubdivOptions.Scheme.LOOP);
        fails("in.obj: face 1 has 4 corners; the Loop scheme needs triangles",
                () -> ControlMesh.builder(P, new int[] {3, 4}, new int[] {0, 1, 4, 1, 2, 5, 4}).source("in.obj").options(loop).build());
        ControlMesh tris = ControlMesh.builder(P, new int[] {3, 3, 3, 3}, new int[] {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4}).options(loop).build();
        assertEquals(4, tris.refinedFaceCount(0));
        assertEquals(16, tris.refinedFaceCount(1));
        assertEquals(64, tris.refinedFaceCount(2));
        assertEquals(64, Subdivision.refine(tris, 2).faceCount());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CatmullClark.refine(tris, 1));
        assertEquals("the mesh has the loop scheme, not Catmull-Clark", e.getMessage());
        ControlMesh quads = ControlMesh.builder(P, SIZES, FV).options(SubdivOptions.DEFAULT.withScheme(SubdivOptions.Scheme.BILINEAR)).build();
        assertEquals(8, quads.refinedFaceCount(1));
        assertEquals(32, Subdivision.refine(quads, 2).faceCount());
        assertEquals(SubdivOptions.Scheme.LOOP, SubdivOptions.Scheme.ofKeyword("loop"));
        assertEquals("bilinear", SubdivOptions.Scheme.BILINEAR.keyword());
        assertEquals(null, SubdivOptions.Scheme.ofKeyword("Loop"));
    }

    @Test
    void refusesMalformedMeshesNamingTheCulprit() {
        fails("face 1 uses vertex 9, but the mesh has 6 vertices",
                () -> ControlMesh.builder(P, SIZES, new int[] {0, 1, 4, 3, 1, 2, 9, 4}).build());
        fails("face 0 uses vertex -1", () -> ControlMesh.builder(P, SIZES, new int[] {0, 1, -1, 3, 1, 2, 5, 4}).build());
        fails("face 1 has 2 corners; a face needs at least 3", () -> ControlMesh.builder(P, new int[] {4, 2}, new int[] {0, 1, 4, 3, 1, 2}).build());
        fails("add up to 8 corners, but 7 vertex indices", () -> ControlMesh.builder(P, SIZES, new int[] {0, 1, 4, 3, 1, 2, 5}).build());
        fails("the mesh has no faces", () -> ControlMesh.builder(P, new int[0], new int[0]).build());
        fails("not a multiple of 3", () -> ControlMesh.builder(new double[] {0, 0}, SIZES, FV).build());
        double[] nan = P.clone();
        nan[7] = Double.NaN;
        fails("vertex 2 has a non-finite coordinate", () -> ControlMesh.builder(nan, SIZES, FV).build());
        fails("in.obj: crease 0: vertices 0 and 2 share no edge", () -> ControlMesh.builder(P, SIZES, FV).source("in.obj").crease(0, 2, 1f).build());
        fails("crease 0 (vertices 0 and 7) names vertex 7", () -> ControlMesh.builder(P, SIZES, FV).crease(0, 7, 1f).build());
        fails("corner 0 names vertex 6", () -> ControlMesh.builder(P, SIZES, FV).corner(6, 1f).build());
        fails("hole 0 names face 2, but the mesh has 2 faces", () -> ControlMesh.builder(P, SIZES, FV).hole(2).build());
        fails("face 1 uses UV 8, but the mesh has 4 UVs",
                () -> ControlMesh.builder(P, SIZES, FV).uvs(new double[8], new int[] {0, 1, 2, 3, 0, 1, 8, 3}).build());
        fails("face 0 corner 2 has no UV",
                () -> ControlMesh.builder(P, SIZES, FV).uvs(new double[8], new int[] {0, 1, -1, 3, 0, 1, 2, 3}).build());
    }

    @Test
    void copiesItsInput() {
        double[] p = P.clone();
        int[] fv = FV.clone();
        ControlMesh m = ControlMesh.builder(p, SIZES, fv).build();
        p[0] = 99;
        fv[0] = 5;
        assertEquals(0, m.positions()[0]);
        assertEquals(0, m.faceVertices()[0]);
        assertEquals(6, m.vertexCount());
        assertEquals(2, m.faceCount());
    }

    @Test
    void boundaryVerticesFollowTheBoundaryOption() {
        // EDGE_ONLY: the corner vertex 0 (one face) moves along its two boundary edges;
        // EDGE_AND_CORNER keeps it in place.
        RefinedMesh edgeOnly = CatmullClark.refine(ControlMesh.builder(P, SIZES, FV).build(), 1);
        assertArrayEquals(new double[] {0.125, 0.125, 0}, slice(edgeOnly.positions(), 0), 1e-15);
        RefinedMesh corners = CatmullClark.refine(ControlMesh.builder(P, SIZES, FV)
                .options(SubdivOptions.DEFAULT.withBoundary(SubdivOptions.Boundary.EDGE_AND_CORNER)).build(), 1);
        assertArrayEquals(new double[] {0, 0, 0}, slice(corners.positions(), 0), 0);
        // A semi-sharp corner is somewhere between.
        RefinedMesh semi = CatmullClark.refine(ControlMesh.builder(P, SIZES, FV).corner(0, 0.5f).build(), 1);
        assertArrayEquals(new double[] {0.0625, 0.0625, 0}, slice(semi.positions(), 0), 1e-15);
    }

    @Test
    void acceptsUnusedVerticesAndKeepsThemInPlace() {
        double[] p = java.util.Arrays.copyOf(P, P.length + 3);
        p[18] = 5;
        RefinedMesh r = CatmullClark.refine(ControlMesh.builder(p, SIZES, FV).build(), 2);
        assertArrayEquals(new double[] {5, 0, 0}, slice(r.positions(), 6), 0);
        assertArrayEquals(new double[] {5, 0, 0}, slice(r.limitPositions(), 6), 0);
    }

    @Test
    void acceptsNonManifoldTopologyAsFarDoes() {
        // Three quads on one edge (0-1): a non-manifold edge is infinitely sharp, so its point
        // is the midpoint, and its end vertices are corners.
        double[] p = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, -1, 0, 0, -1, 0, 1, 0, 1, 0, 0, 1};
        int[] fv = {0, 1, 2, 3, 1, 0, 5, 4, 0, 1, 6, 7};
        ControlMesh m = ControlMesh.builder(p, new int[] {4, 4, 4}, fv).build();
        RefinedMesh r = CatmullClark.refine(m, 1);
        assertArrayEquals(new double[] {0, 0, 0}, slice(r.positions(), 0), 0);
        assertArrayEquals(new double[] {1, 0, 0}, slice(r.positions(), 1), 0);
        int e01 = -1;
        RefinedMesh r0 = CatmullClark.refine(m, 0);
        int[] ev = r0.edgeVertices();
        for (int e = 0; e < r0.edgeCount(); e++) {
            if (Math.min(ev[2 * e], ev[2 * e + 1]) == 0 && Math.max(ev[2 * e], ev[2 * e + 1]) == 1) e01 = r0.vertexCount() + r0.faceCount() + e;
        }
        assertArrayEquals(new double[] {0.5, 0, 0}, slice(r.positions(), e01), 0);

        // A face repeating a vertex, and two faces winding the same way: accepted.
        ControlMesh repeated = ControlMesh.builder(P, new int[] {5, 4}, new int[] {0, 1, 1, 4, 3, 1, 2, 5, 4}).build();
        assertEquals(9, CatmullClark.refine(repeated, 1).faceCount());
        ControlMesh flipped = ControlMesh.builder(P, SIZES, new int[] {0, 1, 4, 3, 4, 5, 2, 1}).build();
        RefinedMesh f = CatmullClark.refine(flipped, 2);
        assertEquals(32, f.faceCount());
        for (double x : f.limitNormals()) assertFalse(Double.isNaN(x));
    }

    @Test
    void holesAreInheritedByChildFaces() {
        RefinedMesh r = CatmullClark.refine(ControlMesh.builder(P, SIZES, FV).hole(1).build(), 2);
        assertTrue(r.hasHoles());
        for (int f = 0; f < r.faceCount(); f++) assertEquals(f >= 16, r.isHole(f), "face " + f);
        assertFalse(CatmullClark.refine(ControlMesh.builder(P, SIZES, FV).build(), 1).hasHoles());
    }

    static double[] slice(double[] a, int v) {
        return new double[] {a[3 * v], a[3 * v + 1], a[3 * v + 2]};
    }
}
