package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Vec3;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;

class RasterizerTest {
    static final int W = 64, H = 48;
    static final int RED = 0xff0000, BLUE = 0x0000ff, GREEN = 0x00ff00;

    /** A square in the plane z = z, from -s to s, counter-clockwise seen from +z. */
    static DisplayGeometry square(double s, double z, boolean withEdges) {
        float[] p = {(float) -s, (float) -s, (float) z, (float) s, (float) -s, (float) z, (float) s, (float) s, (float) z, (float) -s, (float) s, (float) z};
        return new DisplayGeometry(p, new float[] {0, 0, 1}, new int[] {0, 1, 2, 0, 2, 3}, new int[] {0, 0, 0, 0, 0, 0},
                withEdges ? new int[] {0, 1, 1, 2, 2, 3, 3, 0} : new int[0]);
    }

    /** Looking down -z at the origin from z = 10. */
    static OrbitCamera front() {
        OrbitCamera c = new OrbitCamera();
        c.set(Vec3.ZERO, 10, 0, 0);
        return c;
    }

    static int[] render(Rasterizer r, List<Rasterizer.Item> items, OrbitCamera c) {
        int[] frame = new int[W * H];
        r.render(items, c, frame, W, H);
        return frame;
    }


    static int red(int argb) { return argb >> 16 & 255; }
    static int blue(int argb) { return argb & 255; }

    @Test
    void aSquareCoversItsProjectedPixelsExactlyOnce() {
        // Half-size s at distance 10 with a 45 degree fov: s * f / 10 pixels from the centre.
        double f = H / 2.0 / Math.tan(Math.toRadians(45) / 2), s = 1.0, half = s * f / 10;
        try (Rasterizer r = new Rasterizer(1)) {
            int[] frame = render(r, List.of(Rasterizer.Item.faces(square(s, 0, false), RED, BLUE)), front());
            int covered = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    boolean in = Math.abs(x + 0.5 - W / 2.0) < half && Math.abs(y + 0.5 - H / 2.0) < half;
                    boolean drawn = !isBackgroundRow(frame, x, y);
                    if (drawn) covered++;
                    // Pixels whose centres are clearly inside or outside must be so; the rim may go either way.
                    double dx = Math.abs(x + 0.5 - W / 2.0), dy = Math.abs(y + 0.5 - H / 2.0);
                    if (Math.max(dx, dy) < half - 0.01) assertTrue(drawn, "pixel " + x + "," + y + " inside");
                    if (Math.max(dx, dy) > half + 0.01) assertFalse(drawn, "pixel " + x + "," + y + " outside");
                }
            }
            assertEquals(4 * half * half, covered, 2 * 4 * half, "area of the square in pixels");
        }
    }

    @Test
    void pixelsOnBandBoundariesAndFrameEdgesAreCoveredAsTheirCentresSay() {
        // A frame of many 32-row bands and odd sizes; squares whose rims fall across bands and
        // past the frame's edges: every pixel whose centre is clearly in is drawn, clearly out is not.
        int w = 203, h = 171;
        double f = h / 2.0 / Math.tan(Math.toRadians(45) / 2);
        int[] empty = new int[w * h];
        try (Rasterizer r = new Rasterizer(3)) {
            r.render(List.of(), front(), empty, w, h);
            for (double s : new double[] {0.37, 1.0, 1.47, 2.9, 40}) {
                double half = s * f / 10;
                int[] frame = new int[w * h];
                r.render(List.of(Rasterizer.Item.faces(square(s, 0, false), RED, BLUE)), front(), frame, w, h);
                for (int y = 0; y < h; y++) {
                    for (int x = 0; x < w; x++) {
                        boolean drawn = frame[y * w + x] != empty[y * w + x];
                        double d = Math.max(Math.abs(x + 0.5 - w / 2.0), Math.abs(y + 0.5 - h / 2.0));
                        if (d < half - 0.01) assertTrue(drawn, "s " + s + ": pixel " + x + "," + y + " inside");
                        if (d > half + 0.01) assertFalse(drawn, "s " + s + ": pixel " + x + "," + y + " outside");
                    }
                }
            }
        }
    }

    @Test
    void aMeshOfSharedEdgesHasNoPinholes() {
        // A jittered 40 x 30 grid of triangles, split along alternating diagonals, filling more
        // than the view: every pixel centre lies in some triangle, so none may show the background.
        int nx = 40, ny = 30, w = 257, h = 193;
        float[] p = new float[3 * (nx + 1) * (ny + 1)];
        java.util.Random rnd = new java.util.Random(17);
        for (int j = 0; j <= ny; j++) {
            for (int i = 0; i <= nx; i++) {
                int v = j * (nx + 1) + i;
                boolean rim = i == 0 || j == 0 || i == nx || j == ny;
                p[3 * v] = -10 + 20f * i / nx + (rim ? 0 : (rnd.nextFloat() - 0.5f) * 0.3f);
                p[3 * v + 1] = -8 + 16f * j / ny + (rim ? 0 : (rnd.nextFloat() - 0.5f) * 0.3f);
            }
        }
        int[] t = new int[6 * nx * ny];
        int k = 0;
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;
                int[] tri = (i + j) % 2 == 0 ? new int[] {a, b, c, a, c, d} : new int[] {a, b, d, b, c, d};
                for (int x : tri) t[k++] = x;
            }
        }
        DisplayGeometry g = new DisplayGeometry(p, new float[] {0, 0, 1}, t, new int[t.length], new int[0]);
        int[] empty = new int[w * h], frame = new int[w * h];
        try (Rasterizer r = new Rasterizer(2)) {
            r.render(List.of(), front(), empty, w, h);
            r.render(List.of(Rasterizer.Item.faces(g, RED, BLUE)), front(), frame, w, h);
        }
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) assertNotEquals(empty[y * w + x], frame[y * w + x], "pinhole at " + x + "," + y);
        }
    }

    private static int[] background;

    private static boolean isBackgroundRow(int[] frame, int x, int y) {
        if (background == null) {
            background = new int[W * H];
            try (Rasterizer r = new Rasterizer(1)) {
                r.render(List.of(), front(), background, W, H);
            }
        }
        return frame[y * W + x] == background[y * W + x];
    }

    @Test
    void theNearerSurfaceWinsWhateverTheOrder() {
        DisplayGeometry nearSq = square(1, 2, false), farSq = square(2, -2, false);
        try (Rasterizer r = new Rasterizer(2)) {
            for (boolean nearFirst : new boolean[] {true, false}) {
                Rasterizer.Item n = Rasterizer.Item.faces(nearSq, RED, RED), fItem = Rasterizer.Item.faces(farSq, BLUE, BLUE);
                int[] frame = render(r, nearFirst ? List.of(n, fItem) : List.of(fItem, n), front());
                int centre = frame[(H / 2) * W + W / 2];
                assertTrue(red(centre) > 200 && blue(centre) < 100, "red square in front, found " + Integer.toHexString(centre));
                // Beside the small square the large one shows.
                int side = frame[(H / 2) * W + W / 2 + (int) (1.5 * 0.5 * H / Math.tan(Math.toRadians(22.5)) / 10)];
                assertTrue(blue(side) > 200 && red(side) < 100, "blue square behind, found " + Integer.toHexString(side));
            }
        }
    }

    @Test
    void backFacesAreLitWithTheFlippedNormalAndTheBackTint() {
        Rasterizer.Item sq = Rasterizer.Item.faces(square(1, 0, false), RED, BLUE);
        try (Rasterizer r = new Rasterizer(1)) {
            int fromFront = render(r, List.of(sq), front())[(H / 2) * W + W / 2];
            OrbitCamera behind = new OrbitCamera();
            behind.set(Vec3.ZERO, 10, Math.PI, 0);
            int fromBehind = render(r, List.of(sq), behind)[(H / 2) * W + W / 2];
            assertTrue(red(fromFront) > 200 && blue(fromFront) < 100, "front: red, lit, found " + Integer.toHexString(fromFront));
            assertTrue(blue(fromBehind) > 200 && red(fromBehind) < 100, "back: blue, lit as brightly, found " + Integer.toHexString(fromBehind));
            assertEquals(Rasterizer.shades(RED)[255], fromFront, "facing the headlight: the brightest shade");
            assertEquals(Rasterizer.shades(BLUE)[255], fromBehind);
        }
    }

    @Test
    void edgesShowOnTheirFaceButNotBehindAnother() {
        DisplayGeometry sq = square(1, 0, true);
        try (Rasterizer r = new Rasterizer(1)) {
            int line = 0xff000000 | GREEN;
            int[] frame = render(r, List.of(Rasterizer.Item.faces(sq, RED, BLUE), Rasterizer.Item.edges(sq, GREEN)), front());
            assertTrue(count(frame, line) > 40, "the square's outline is drawn over it: " + count(frame, line));
            // A larger square in front hides the outline.
            frame = render(r, List.of(Rasterizer.Item.faces(square(3, 1, false), RED, BLUE), Rasterizer.Item.edges(sq, GREEN)), front());
            assertEquals(0, count(frame, line));
        }
    }

    @Test
    void aSurfaceCrossingTheNearPlaneIsCutNotDropped() {
        OrbitCamera c = front();
        c.set(new Vec3(0, -0.5, 0), 0.5, 0, Math.toRadians(30));
        // The big floor square below the eye reaches behind it.
        float[] p = {-50, -1, -50, 50, -1, -50, 50, -1, 50, -50, -1, 50};
        DisplayGeometry floor = new DisplayGeometry(p, new float[] {0, 1, 0}, new int[] {0, 2, 1, 0, 3, 2}, new int[6], new int[] {0, 1, 1, 2, 2, 3, 3, 0});
        try (Rasterizer r = new Rasterizer(2)) {
            int[] frame = render(r, List.of(Rasterizer.Item.faces(floor, RED, BLUE), Rasterizer.Item.edges(floor, GREEN)), c);
            int drawn = 0;
            for (int y = 0; y < H; y++) for (int x = 0; x < W; x++) if (!isBackgroundRow(frame, x, y)) drawn++;
            assertTrue(drawn > W * H / 2, "the floor fills most of the frame: " + drawn);
        }
    }

    @Test
    void theFrameIsTheSameForAnyNumberOfThreads() {
        ControlMesh cube = ControlMesh.builder(new double[] {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1},
                new int[] {4, 4, 4, 4, 4, 4},
                new int[] {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 0, 4, 7, 3}).build();
        DisplayGeometry smooth = DisplayGeometry.smoothed(CatmullClark.refine(cube, 3)), cage = DisplayGeometry.lattice(cube);
        List<Rasterizer.Item> items = List.of(Rasterizer.Item.faces(smooth, RED, BLUE), Rasterizer.Item.edges(cage, GREEN));
        OrbitCamera c = new OrbitCamera();
        c.set(Vec3.ZERO, 4, 0.6, 0.4);
        int w = 200, h = 150;
        int[] one = new int[w * h], three = new int[w * h];
        try (Rasterizer a = new Rasterizer(1); Rasterizer b = new Rasterizer(3)) {
            a.render(items, c, one, w, h);
            b.render(items, c, three, w, h);
            b.render(items, c, three, w, h);
        }
        assertArrayEquals(one, three);
        assertTrue(count(one, 0xff000000 | GREEN) > 0);
    }

    @Test
    void edgesAreDrawnAfterEveryFaceWhateverTheItemsOrder() {
        DisplayGeometry sq = square(1, 0, true), front = square(0.5, 0.5, false);
        Rasterizer.Item edges = Rasterizer.Item.edges(sq, GREEN), faces = Rasterizer.Item.faces(sq, RED, BLUE), near = Rasterizer.Item.faces(front, BLUE, RED);
        try (Rasterizer r = new Rasterizer(2)) {
            int[] a = render(r, List.of(edges, faces, near), front());
            int[] b = render(r, List.of(faces, near, edges), front());
            assertArrayEquals(b, a);
            assertTrue(count(a, 0xff000000 | GREEN) > 40);
        }
    }

    static int count(int[] frame, int argb) {
        int n = 0;
        for (int v : frame) if (v == argb) n++;
        return n;
    }
}
