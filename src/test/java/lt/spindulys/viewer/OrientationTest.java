package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.ImageDiff;
import lt.spindulys.subdiv.CatmullClark;

/** Which side is the inside: the enclosed volume for a closed surface, the winding for an open one. */
class OrientationTest {
    static final int W = 120, H = 90;

    @TempDir Path dir;

    /** The OBJ with every face's corners in the opposite order. */
    static String reversed(String obj) {
        return obj.lines().map(l -> {
            if (!l.startsWith("f ")) return l;
            List<String> c = new ArrayList<>(Arrays.asList(l.substring(2).trim().split("\\s+")));
            java.util.Collections.reverse(c);
            return "f " + String.join(" ", c);
        }).collect(Collectors.joining("\n", "", "\n"));
    }

    private ViewerModel open(String name, String obj) throws IOException {
        Path f = dir.resolve(name);
        Files.writeString(f, obj);
        List<String> errors = new ArrayList<>();
        ViewerModel m = new ViewerModel(Runnable::run, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() {}
            @Override public void error(String message) { errors.add(message); }
        });
        m.viewport(W, H);
        m.open(List.of(f));
        assertEquals(List.of(), errors);
        return m;
    }

    private static int[] picture(ViewerModel m) {
        int[] frame = new int[W * H];
        try (Rasterizer r = new Rasterizer(1)) {
            r.render(m.drawList(), m.camera(), frame, W, H);
        }
        return frame;
    }

    @Test
    void theSignedVolumeFollowsTheWinding() throws IOException {
        ViewedSurface ccw = open("ccw.obj", ViewerModelTest.CUBE_OBJ).selected(), cw = open("cw.obj", reversed(ViewerModelTest.CUBE_OBJ)).selected();
        for (boolean smooth : new boolean[] {false, true}) {
            var ccwMesh = CatmullClark.refine(ccw.control(ccw.scheme(), ccw.boundary()), 0);
            var cwMesh = CatmullClark.refine(cw.control(cw.scheme(), cw.boundary()), 0);
            DisplayGeometry a = smooth ? DisplayGeometry.smoothed(ccwMesh) : DisplayGeometry.polyhedron(ccwMesh);
            DisplayGeometry b = smooth ? DisplayGeometry.smoothed(cwMesh) : DisplayGeometry.polyhedron(cwMesh);
            assertEquals(8, a.signedVolume(), 1e-9, "the 2 x 2 x 2 cube, counter-clockwise");
            assertEquals(-8, b.signedVolume(), 1e-9, "the same cube wound clockwise");
            assertSame(a, a.outward(), "wound outwards already: nothing to turn");
            assertEquals(8, b.outward().signedVolume(), 1e-9, "turned outwards");
            ViewedSurface.Key k = new ViewedSurface.Key(0, ccw.scheme(), ccw.boundary(), smooth);
            assertEquals(8, cw.build(k).signedVolume(), 1e-9, "the viewer shows a closed surface wound outwards");
        }
        assertTrue(ccw.closed());
        assertTrue(cw.closed());
        assertFalse(open("grid.obj", ViewerModelTest.GRID_OBJ).selected().closed(), "a sheet has a boundary");
        // One face wound against its neighbours (as gourd.obj's two end caps are): still closed.
        String oneFlipped = ViewerModelTest.CUBE_OBJ.replace("f 1 2 4 3", "f 3 4 2 1");
        assertTrue(open("mixed.obj", oneFlipped).selected().closed());
        String oneMissing = ViewerModelTest.CUBE_OBJ.replace("f 1 2 4 3\n", "");
        assertFalse(open("box.obj", oneMissing).selected().closed(), "a box without its lid is open");
    }

    @Test
    void aClosedSurfaceWoundClockwiseShowsItsOutsideInItsColour() throws IOException {
        for (DisplayMode mode : new DisplayMode[] {DisplayMode.SMOOTHED, DisplayMode.POLYHEDRON}) {
            ViewerModel ccw = open("ccw.obj", ViewerModelTest.CUBE_OBJ), cw = open("cw.obj", reversed(ViewerModelTest.CUBE_OBJ));
            ccw.mode(mode);
            cw.mode(mode);
            int[] a = picture(ccw), b = picture(cw);
            // The same surface and normals (flipped twice); only the diagonal fans of the faces may differ by a pixel.
            ImageDiff.Result d = ImageDiff.compare(W, H, a, b, 3);
            assertTrue(d.fractionOver() < 0.01, mode + ": the clockwise cube looks like the counter-clockwise one: " + d);
            // One face wound against its neighbours, as gourd.obj's end caps are: turned to agree with them
            // (refinement sees those edges as non-manifold, so the smooth surface differs; the faces all face out).
            ViewerModel mixed = open("mixed.obj", ViewerModelTest.CUBE_OBJ.replace("f 1 2 4 3", "f 3 4 2 1"));
            mixed.mode(mode);
            DisplayGeometry g = mixed.selected().facesItem().geometry();
            assertTrue(consistent(g), mode + ": every edge run one way by one triangle and the other way by the other");
            assertTrue(g.signedVolume() > 0, mode + ": and outwards");
        }
        // At level 0 the polyhedron is the cube itself: the same picture as the cube wound right.
        ViewerModel ccw = open("ccw.obj", ViewerModelTest.CUBE_OBJ), mixed = open("mixed.obj", ViewerModelTest.CUBE_OBJ.replace("f 1 2 4 3", "f 3 4 2 1"));
        for (ViewerModel m : List.of(ccw, mixed)) {
            m.mode(DisplayMode.POLYHEDRON);
            m.level(0);
        }
        ImageDiff.Result d = ImageDiff.compare(W, H, picture(ccw), picture(mixed), 3);
        assertTrue(d.fractionOver() < 0.01, "the face wound the other way shows its outside: " + d);
    }

    /** Whether every edge two triangles share is run in opposite directions by them. */
    static boolean consistent(DisplayGeometry g) {
        java.util.Map<Long, Integer> directed = new java.util.HashMap<>();
        int[] t = g.triangles();
        for (int i = 0; i < t.length; i++) {
            long a = t[i], b = t[i - i % 3 + (i % 3 + 1) % 3];
            if (directed.merge(a << 32 | b, 1, Integer::sum) > 1) return false;
        }
        return true;
    }

    @Test
    void anOpenSurfaceKeepsItsWinding() throws IOException {
        ViewerModel up = open("grid.obj", ViewerModelTest.GRID_OBJ), down = open("flipped.obj", reversed(ViewerModelTest.GRID_OBJ));
        ViewedSurface s = down.selected();
        assertArrayEquals(Rasterizer.Item.faces(s.facesItem().geometry(), s.rgb(), 0).front(), s.facesItem().front(),
                "the winding decides which side of a sheet is its front");
        // Seen from the same side, the flipped sheet shows the other side's tint.
        ImageDiff.Result d = ImageDiff.compare(W, H, picture(up), picture(down), 3);
        assertTrue(d.fractionOver() > 0.05, "the two sides of a sheet look different: " + d);
    }
}
