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
            ViewedSurface.Key k = new ViewedSurface.Key(0, ccw.boundary(), smooth);
            assertEquals(8, ccw.build(k).signedVolume(), 1e-9, "the 2 x 2 x 2 cube, counter-clockwise");
            assertEquals(-8, cw.build(k).signedVolume(), 1e-9, "the same cube wound clockwise");
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
            ViewedSurface s = cw.selected();
            assertArrayEquals(Rasterizer.Item.faces(cw.selected().facesItem().geometry(), s.rgb(), ViewedSurface.backTint(s.rgb())).back(),
                    s.facesItem().front(), mode + ": clockwise winding's front faces are the inside");
        }
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
