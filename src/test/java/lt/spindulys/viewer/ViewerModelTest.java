package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.event.KeyEvent;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.cli.Main;
import lt.spindulys.subdiv.SubdivOptions;

/** The viewer's logic without a window: opening, modes, levels, boundary rules, unwraps, errors, keys and mouse. */
class ViewerModelTest {
    @TempDir Path dir;

    static final Path CUBE_DAT = Path.of("scenes/models/cube.dat"), CUBE_TEX = Path.of("scenes/models/cube.tex");

    static final String CUBE_OBJ = """
            v -1 -1 1
            v 1 -1 1
            v -1 1 1
            v 1 1 1
            v -1 1 -1
            v 1 1 -1
            v -1 -1 -1
            v 1 -1 -1
            f 1 2 4 3
            f 3 4 6 5
            f 5 6 8 7
            f 7 8 2 1
            f 2 8 6 4
            f 7 1 3 5
            t crease 2/1/0 0 1 10
            """;

    /** A 2x2 grid of quads: open, with a boundary the rules treat differently. */
    static final String GRID_OBJ = """
            v 0 0 0
            v 1 0 0
            v 2 0 0
            v 0 1 0
            v 1 1 1
            v 2 1 0
            v 0 2 0
            v 1 2 0
            v 2 2 0
            f 1 2 5 4
            f 2 3 6 5
            f 4 5 8 7
            f 5 6 9 8
            """;

    final List<String> errors = new ArrayList<>();
    int changes;

    /** A model whose background work runs at once, on the test's thread. */
    ViewerModel model() {
        return new ViewerModel(Runnable::run, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() { changes++; }
            @Override public void error(String message) { errors.add(message); }
        });
    }

    Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    static DisplayGeometry faces(ViewerModel m) {
        for (Rasterizer.Item it : m.drawList()) if (it.drawTriangles()) return it.geometry();
        return null;
    }

    static int edgeItems(ViewerModel m) {
        int n = 0;
        for (Rasterizer.Item it : m.drawList()) if (it.drawEdges()) n++;
        return n;
    }

    @Test
    void opensSmoothedAtALevelThatKeepsTheFacesFew() throws IOException {
        ViewerModel m = model();
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        assertEquals(List.of(), errors);
        assertEquals(1, m.surfaces().size());
        ViewedSurface s = m.selected();
        assertEquals("cube.obj", s.name());
        assertEquals(DisplayMode.SMOOTHED, s.mode());
        assertEquals(3, s.level());
        // 6 quads -> 6 * 4^3 quads -> two triangles each.
        assertEquals(2 * 6 * 64, faces(m).triangleCount());
        assertEquals(0, edgeItems(m));
        assertEquals(0, m.pending());
        // The view was fitted: the eye is outside the cube, looking at its centre.
        assertTrue(m.camera().distance() > 2);
        assertEquals(0, m.camera().target().length(), 1e-9);
    }

    @Test
    void modesLevelsAndTheCageChangeWhatIsDrawn() throws IOException {
        ViewerModel m = model();
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        m.mode(DisplayMode.POLYHEDRON);
        m.level(0);
        DisplayGeometry poly = faces(m);
        assertEquals(12, poly.triangleCount(), "the control mesh's 6 quads, fanned");
        assertEquals(6, poly.normals().length / 3, "one flat normal per face");
        m.levelUp();
        assertEquals(1, m.selected().level());
        assertEquals(48, faces(m).triangleCount());
        m.levelDown();
        m.levelDown();
        assertEquals(0, m.selected().level(), "level stops at 0");
        assertSame(poly, faces(m), "a level shown before comes from the cache");

        m.mode(DisplayMode.LATTICE);
        assertNull(faces(m));
        assertEquals(1, edgeItems(m));
        assertEquals(12, m.drawList().get(0).geometry().edgeCount(), "the cube cage's 12 edges");

        m.mode(DisplayMode.SMOOTHED);
        m.toggleCage();
        assertNotNull(faces(m));
        assertEquals(1, edgeItems(m));
        assertTrue(m.drawList().get(m.drawList().size() - 1).drawEdges(), "cages are drawn after every surface");
        m.toggleCage();
        assertEquals(0, edgeItems(m));
        assertEquals(List.of(), errors);
    }

    @Test
    void aLevelTooDeepIsRefusedWithTheMessageAndChangesNothing() throws IOException {
        ViewerModel m = model();
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        m.level(8);
        assertEquals(8, m.selected().level(), "6 * 4^8 faces are allowed");
        m.levelUp();
        assertEquals(List.of("subdivision level must be between 0 and 8, found 9"), errors);
        assertEquals(8, m.selected().level());
    }

    @Test
    void theBoundaryRuleChangesAnOpenSurface() throws IOException {
        ViewerModel m = model();
        m.open(List.of(write("grid.obj", GRID_OBJ)));
        m.level(2);
        assertEquals(SubdivOptions.Boundary.EDGE_ONLY, m.selected().boundary(), "the tags' default");
        DisplayGeometry edgeOnly = faces(m);
        m.boundary(SubdivOptions.Boundary.EDGE_AND_CORNER);
        DisplayGeometry corners = faces(m);
        assertNotSame(edgeOnly, corners);
        // Corner (0,0,0) is pinned with EDGE_AND_CORNER, pulled inwards with EDGE_ONLY.
        assertTrue(has(corners, 0, 0, 0));
        assertFalse(has(edgeOnly, 0, 0, 0));
        m.boundary(SubdivOptions.Boundary.NONE);
        assertTrue(faces(m).triangleCount() < corners.triangleCount(), "without boundary interpolation the boundary faces go");
        ViewerSnapshot.Surface snap = m.snapshot().surfaces().get(0);
        assertEquals(SubdivOptions.Boundary.NONE, snap.boundary());
        assertEquals(SubdivOptions.Boundary.NONE, snap.control().options().boundary());
        assertEquals(SubdivOptions.Boundary.NONE, snap.input().options().boundary());
    }


    @Test
    void theSchemeIsTheFilesAndCanBeChanged() throws IOException {
        ViewerModel m = model();
        m.open(List.of(write("oct.obj", lt.spindulys.scene.TestMeshes.OCTAHEDRON_OBJ + "t scheme 0/0/1 loop\n")));
        ViewedSurface s = m.selected();
        assertEquals(SubdivOptions.Scheme.LOOP, s.scheme(), "the file's tag");
        assertNull(s.nonTriangle());
        m.level(2);
        DisplayGeometry loop = faces(m);
        assertEquals(SubdivOptions.Scheme.LOOP, s.shownKey().scheme());
        m.scheme(SubdivOptions.Scheme.BILINEAR);
        assertEquals(List.of(), errors);
        assertEquals(SubdivOptions.Scheme.BILINEAR, s.scheme());
        assertNotSame(loop, faces(m), "another scheme, another geometry");
        assertEquals(8 * 16, loop.triangleCount(), "Loop: each triangle into four, twice");
        assertEquals(2 * 8 * 3 * 4, faces(m).triangleCount(), "bilinear: three quads per triangle, then four each, two triangles a quad");
        assertEquals(SubdivOptions.Scheme.BILINEAR, s.shownKey().scheme());
        ViewerSnapshot.Surface snap = m.snapshot().surfaces().get(0);
        assertEquals(SubdivOptions.Scheme.BILINEAR, snap.scheme());
        assertEquals(SubdivOptions.Scheme.BILINEAR, snap.control().options().scheme(), "the plugins refine with the viewer's scheme");
        assertEquals(SubdivOptions.Scheme.BILINEAR, snap.input().options().scheme());
        assertEquals(lt.spindulys.plugin.DisplayedSurface.Scheme.BILINEAR, PluginAdapter.surfaces(m.snapshot()).get(0).scheme());
        m.scheme(SubdivOptions.Scheme.LOOP);
        assertSame(loop, faces(m), "back to Loop: the cached geometry");
    }

    @Test
    void loopIsRefusedForACageWithOtherFacesThanTriangles() throws IOException {
        ViewerModel m = model();
        Path cube = write("cube.obj", CUBE_OBJ);
        m.open(List.of(cube));
        ViewedSurface s = m.selected();
        assertEquals(SubdivOptions.Scheme.CATMARK, s.scheme());
        assertEquals("face 0 has 4 corners", s.nonTriangle());
        assertFalse(SchemeChoice.enabled(s, SubdivOptions.Scheme.LOOP));
        assertTrue(SchemeChoice.enabled(s, SubdivOptions.Scheme.BILINEAR));
        assertEquals("Loop needs a cage of triangles: face 0 has 4 corners", SchemeChoice.tooltip(s, SubdivOptions.Scheme.LOOP));
        assertNull(SchemeChoice.tooltip(s, SubdivOptions.Scheme.CATMARK));
        m.scheme(SubdivOptions.Scheme.LOOP);
        assertEquals(List.of(cube + ": face 0 has 4 corners; the Loop scheme needs triangles"), errors);
        assertEquals(SubdivOptions.Scheme.CATMARK, s.scheme(), "refused: nothing changes");
        // A Loop file with a quad is refused when it is opened, as the scene and render subdivide refuse it.
        errors.clear();
        Path bad = write("bad.obj", CUBE_OBJ + "t scheme 0/0/1 loop\n");
        m.open(List.of(bad));
        assertEquals(List.of(bad + ": face 0 has 4 corners; the Loop scheme needs triangles"), errors);
        assertEquals(1, m.surfaces().size());
        // No surface selected: nothing to choose.
        assertFalse(SchemeChoice.enabled(null, SubdivOptions.Scheme.CATMARK));
    }

    /** An icosahedron: twenty triangles, so that level 8 fits the viewer under Catmull-Clark (60 quads at level 1) but not under Loop (80 triangles). */
    static final String ICOSAHEDRON_OBJ = """
            v -1 1.618034 0
            v 1 1.618034 0
            v -1 -1.618034 0
            v 1 -1.618034 0
            v 0 -1 1.618034
            v 0 1 1.618034
            v 0 -1 -1.618034
            v 0 1 -1.618034
            v 1.618034 0 -1
            v 1.618034 0 1
            v -1.618034 0 -1
            v -1.618034 0 1
            f 1 12 6
            f 1 6 2
            f 1 2 8
            f 1 8 11
            f 1 11 12
            f 2 6 10
            f 6 12 5
            f 12 11 3
            f 11 8 7
            f 8 2 9
            f 4 10 5
            f 4 5 3
            f 4 3 7
            f 4 7 9
            f 4 9 10
            f 5 10 6
            f 3 5 12
            f 7 3 11
            f 9 7 8
            f 10 9 2
            """;

    @Test
    void aSchemeWhoseLevelHasTooManyFacesIsRefused() throws IOException {
        ViewerModel m = model();
        m.open(List.of(write("ico.obj", ICOSAHEDRON_OBJ)));
        m.mode(DisplayMode.LATTICE); // nothing is refined: only the counts matter here
        m.level(8);
        assertEquals(List.of(), errors, "Catmull-Clark: 60 * 4^7 = 983040 faces at level 8");
        m.scheme(SubdivOptions.Scheme.LOOP);
        assertEquals(1, errors.size());
        assertTrue(errors.get(0).endsWith("subdivision level 8 would show 1310720 faces, more than the 1048576 the viewer draws"
                + " (choose a lower level; the ray-tracing plugin renders the limit surface)"), errors.get(0));
        assertEquals(SubdivOptions.Scheme.CATMARK, m.selected().scheme());
        m.level(7);
        m.scheme(SubdivOptions.Scheme.LOOP);
        assertEquals(SubdivOptions.Scheme.LOOP, m.selected().scheme(), "20 * 4^7 Loop triangles at level 7");
        errors.clear();
        m.level(8);
        assertEquals(1, errors.size(), "and the level is checked with the Loop counts");
    }

    static boolean has(DisplayGeometry g, float x, float y, float z) {
        float[] p = g.positions();
        for (int i = 0; i < p.length; i += 3) if (p[i] == x && p[i + 1] == y && p[i + 2] == z) return true;
        return false;
    }

    @Test
    void aDatPicksUpTheUnwrapBesideItAndATexAttachesToTheSelectedSurface() throws IOException {
        Path dat = dir.resolve("cube.dat");
        Files.copy(CUBE_DAT, dat);
        ViewerModel m = model();
        m.open(List.of(dat));
        assertNull(m.selected().input().mesh().uvs(), "no cube.tex beside it yet");
        m.open(List.of(CUBE_TEX));
        assertEquals(List.of(), errors);
        assertNotNull(m.selected().input().mesh().uvs());
        assertEquals(CUBE_TEX, m.selected().unwrap());
        assertNotNull(m.snapshot().surfaces().get(0).control().uvs(), "the plugin gets the UVs");

        Files.copy(CUBE_TEX, dir.resolve("cube.tex"));
        ViewerModel m2 = model();
        m2.open(List.of(dat));
        assertEquals(dir.resolve("cube.tex"), m2.selected().unwrap());
        assertNotNull(m2.selected().input().mesh().uvs());
    }

    @Test
    void badInputIsReportedAsTheCommandLineReportsItAndTheViewerGoesOn() throws IOException {
        Path bad = write("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 x\n");
        ViewerModel m = model();
        m.open(List.of(bad, write("cube.obj", CUBE_OBJ)));
        assertEquals(1, errors.size());
        assertEquals(1, m.surfaces().size(), "the good file still opens");
        assertEquals(cliError("subdivide", bad.toString(), "--level", "1", "-o", dir.resolve("o.obj").toString()), errors.get(0));
        assertTrue(errors.get(0).startsWith(bad + ":3:"), errors.get(0));

        // A .tex that does not fit the selected surface: the unwrap's line, the surface unchanged.
        Path tex = write("short.tex", "2\n0 0\n1 1\n");
        m.open(List.of(tex));
        assertEquals(2, errors.size());
        assertTrue(errors.get(1).startsWith(tex + ":1:1: the unwrap has 2 corners"), errors.get(1));
        assertNull(m.selected().input().mesh().uvs());

        m.open(List.of(write("notes.txt", "hello")));
        assertEquals(dir.resolve("notes.txt") + ": the viewer opens .obj and .dat meshes and .tex unwraps, found a .txt file", errors.get(2));
        m.open(List.of(dir.resolve("missing.dat")));
        assertEquals(cliError("subdivide", dir.resolve("missing.dat").toString(), "--level", "1", "-o", dir.resolve("o.obj").toString()), errors.get(3));
        assertEquals(0, m.pending());
        assertEquals(1, m.surfaces().size());
    }

    @Test
    void aMeshWithoutFacesIsRefusedWhenOpened() throws IOException {
        ViewerModel m = model();
        Path points = write("points.obj", "v 0 0 0\nv 1 0 0\n");
        m.open(List.of(points));
        assertEquals(List.of(points + ": the mesh has no faces"), errors);
        assertEquals(0, m.surfaces().size());
        assertEquals(List.of(), m.drawList());
    }

    @Test
    void anUnwrapWithNothingOpenIsAnError() {
        ViewerModel m = model();
        m.open(List.of(CUBE_TEX));
        assertEquals(1, errors.size());
        assertTrue(errors.get(0).contains("no surface is open"), errors.get(0));
        assertEquals(0, m.pending());
    }

    /** The line `render ARGS` prints on stderr. */
    static String cliError(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(args, new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertNotEquals(0, status);
        String e = err.toString(StandardCharsets.UTF_8);
        assertEquals(1, e.lines().count(), e);
        return e.strip();
    }

    @Test
    void severalSurfacesCloseAndSnapshot() throws IOException {
        ViewerModel m = model();
        m.viewport(800, 600);
        m.open(List.of(write("a.obj", CUBE_OBJ), write("b.obj", GRID_OBJ)));
        assertEquals(2, m.surfaces().size());
        assertEquals(1, m.selectedIndex(), "the last opened is selected");
        assertNotEquals(m.surfaces().get(0).rgb(), m.surfaces().get(1).rgb());
        m.select(0);
        m.mode(DisplayMode.LATTICE);
        assertEquals(DisplayMode.SMOOTHED, m.surfaces().get(1).mode(), "modes are per surface");
        ViewerSnapshot snap = m.snapshot();
        assertEquals(List.of("a.obj", "b.obj"), snap.surfaces().stream().map(ViewerSnapshot.Surface::name).toList());
        assertEquals(DisplayMode.LATTICE, snap.surfaces().get(0).mode());
        assertEquals(800, snap.view().width());
        assertEquals(600, snap.view().height());
        assertEquals(m.camera().eye(), snap.view().eye());
        assertEquals(45, snap.view().fovDegrees());
        m.closeSelected();
        assertEquals(List.of("b.obj"), m.surfaces().stream().map(ViewedSurface::name).toList());
        assertEquals(0, m.selectedIndex());
        m.closeSelected();
        assertEquals(-1, m.selectedIndex());
        assertEquals(List.of(), m.drawList());
        m.levelUp();
        m.mode(DisplayMode.POLYHEDRON);
        assertEquals(List.of(), errors, "actions on no surface do nothing");
    }

    @Test
    void whileALevelIsRefinedTheLastGeometryStaysOnScreen() throws IOException {
        ArrayDeque<Runnable> work = new ArrayDeque<>();
        ViewerModel m = new ViewerModel(work::add, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() { changes++; }
            @Override public void error(String message) { errors.add(message); }
        });
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        assertEquals(1, m.pending());
        assertEquals(0, m.surfaces().size(), "read in the background");
        work.poll().run();
        assertEquals(1, m.surfaces().size());
        work.poll().run();
        DisplayGeometry level3 = faces(m);
        assertNotNull(level3);
        m.levelUp();
        m.levelDown();
        m.levelDown();
        assertSame(level3, faces(m), "level 3 is cached");
        assertEquals(2, m.pending(), "levels 4 and 2 queued (3 came from the cache)");
        assertFalse(m.selected().upToDate());
        while (!work.isEmpty()) work.poll().run();
        assertEquals(0, m.pending());
        assertTrue(m.selected().upToDate());
        assertEquals(2 * 6 * 16, faces(m).triangleCount());
        assertNull(m.selected().cached(new ViewedSurface.Key(4, SubdivOptions.Scheme.CATMARK, SubdivOptions.Boundary.EDGE_ONLY, true)),
                "level 4, no longer wanted when its turn came, was not built");
        assertNotNull(m.selected().cached(new ViewedSurface.Key(3, SubdivOptions.Scheme.CATMARK, SubdivOptions.Boundary.EDGE_ONLY, true)));
    }

    @Test
    void aLevelAskedForAgainWhileItsSkippedBuildIsStillQueuedIsBuilt() throws IOException {
        ArrayDeque<Runnable> work = new ArrayDeque<>(), ui = new ArrayDeque<>();
        ViewerModel m = new ViewerModel(work::add, ui::add, new ViewerModel.Listener() {
            @Override public void changed() { changes++; }
            @Override public void error(String message) { errors.add(message); }
        });
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        while (!work.isEmpty() || !ui.isEmpty()) (work.isEmpty() ? ui : work).poll().run();
        m.levelUp();
        m.levelUp();
        // Level 4's build starts while 5 is wanted: skipped, its end posted to the event thread...
        work.poll().run();
        // ...where the user has gone back to 4 before that end arrives.
        m.levelDown();
        while (!work.isEmpty() || !ui.isEmpty()) (work.isEmpty() ? ui : work).poll().run();
        assertEquals(List.of(), errors);
        assertEquals(4, m.selected().level());
        assertEquals(0, m.pending());
        assertTrue(m.selected().upToDate(), "level 4 is built and shown, not left asked for forever");
        assertEquals(2 * 6 * 256, faces(m).triangleCount());
    }

    @Test
    void aLevelWithMoreFacesThanTheViewerDrawsIsRefusedAtOnce() throws IOException {
        // A 5 x 4 grid: 20 faces, 20 * 4^7 = 327,680 at level 7, 1,310,720 at level 8.
        StringBuilder obj = new StringBuilder();
        for (int y = 0; y <= 4; y++) for (int x = 0; x <= 5; x++) obj.append("v ").append(x).append(' ').append(y).append(" 0\n");
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 5; x++) {
                int a = y * 6 + x + 1;
                obj.append("f ").append(a).append(' ').append(a + 1).append(' ').append(a + 7).append(' ').append(a + 6).append('\n');
            }
        }
        Path grid = write("grid.obj", obj.toString());
        ArrayDeque<Runnable> work = new ArrayDeque<>();
        ViewerModel m = new ViewerModel(work::add, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() { changes++; }
            @Override public void error(String message) { errors.add(message); }
        });
        m.open(List.of(grid));
        while (!work.isEmpty()) work.poll().run();
        m.level(7);
        assertEquals(7, m.selected().level());
        work.clear();
        m.levelUp();
        assertEquals(List.of(grid + ": subdivision level 8 would show 1310720 faces, more than the 1048576 the viewer draws"
                + " (choose a lower level; the ray-tracing plugin renders the limit surface)"), errors);
        assertEquals(7, m.selected().level());
        assertTrue(work.isEmpty(), "nothing is refined for a refused level");
    }

    @Test
    void movingTheCameraKeepsTheDrawListAndSaysOnlyTheViewChanged() throws IOException {
        int[] views = {0};
        ViewerModel m = new ViewerModel(Runnable::run, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() { changes++; }
            @Override public void error(String message) { errors.add(message); }
            @Override public void viewChanged() { views[0]++; }
        });
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        List<Rasterizer.Item> before = m.drawList();
        int changesBefore = changes;
        m.orbit(10, 5);
        m.pan(3, -2);
        m.zoom(1.2);
        assertSame(before, m.drawList(), "nothing is rebuilt (or allocated) for a frame while orbiting");
        assertEquals(3, views[0]);
        assertEquals(changesBefore, changes);
        m.toggleCage();
        assertNotSame(before, m.drawList());
    }

    @Test
    void aFolderOrNothingWithoutAKnownExtensionIsNamedForWhatItIs() throws IOException {
        ViewerModel m = model();
        Path folder = Files.createDirectory(dir.resolve("meshes")), missing = dir.resolve("gone");
        m.open(List.of(folder, missing));
        assertEquals(List.of(folder + ": the viewer opens .obj and .dat meshes and .tex unwraps, found a path that is a directory, not a regular file",
                missing + ": the viewer opens .obj and .dat meshes and .tex unwraps, found nothing there (not found)"), errors);
        assertEquals(0, m.surfaces().size());
        assertEquals(0, m.pending());
    }

    @Test
    void aBuildThatFailsKeepsWhatIsShownAndTakesTheSettingsBack() throws IOException {
        ArrayDeque<Runnable> work = new ArrayDeque<>();
        ViewerModel m = new ViewerModel(work::add, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() { changes++; }
            @Override public void error(String message) { errors.add(message); }
        });
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        while (!work.isEmpty()) work.poll().run();
        DisplayGeometry level3 = faces(m);
        m.level(6);
        assertEquals(6, m.selected().level());
        // By the time the build runs, the heap has gone (as if other surfaces had taken it).
        try (var cap = lt.spindulys.limits.HeapBudget.cap(1 << 20)) {
            work.poll().run();
        }
        assertEquals(1, errors.size());
        assertTrue(errors.get(0).startsWith("subdivision level 6 of this mesh (24576 faces"), errors.get(0));
        assertEquals(3, m.selected().level(), "back to the level on screen");
        assertSame(level3, faces(m));
        assertTrue(m.selected().upToDate());
        assertEquals(0, m.pending());
        m.levelUp();
        while (!work.isEmpty()) work.poll().run();
        assertEquals(4, m.selected().level(), "and it goes on from there");
        assertEquals(2 * 6 * 256, faces(m).triangleCount());
    }

    @Test
    void keysAndMouseDriveTheModel() throws IOException {
        ViewerModel m = model();
        m.viewport(640, 480);
        m.open(List.of(write("cube.obj", CUBE_OBJ)));
        ViewerInput in = new ViewerInput(m);
        double yaw = m.camera().yaw();
        assertTrue(in.key(KeyEvent.VK_LEFT, KeyEvent.CHAR_UNDEFINED));
        assertNotEquals(yaw, m.camera().yaw());
        double d = m.camera().distance();
        in.key(KeyEvent.VK_PLUS, '+');
        assertEquals(d / ViewerInput.ZOOM_STEP, m.camera().distance(), 1e-12);
        in.key(KeyEvent.VK_MINUS, '-');
        assertEquals(d, m.camera().distance(), 1e-12);
        in.key(KeyEvent.VK_1, '1');
        assertEquals(DisplayMode.POLYHEDRON, m.selected().mode());
        in.key(KeyEvent.VK_2, '2');
        assertEquals(DisplayMode.LATTICE, m.selected().mode());
        in.key(KeyEvent.VK_3, '3');
        assertEquals(DisplayMode.SMOOTHED, m.selected().mode());
        in.key(KeyEvent.VK_PAGE_DOWN, KeyEvent.CHAR_UNDEFINED);
        assertEquals(2, m.selected().level());
        in.key(KeyEvent.VK_PAGE_UP, KeyEvent.CHAR_UNDEFINED);
        assertEquals(3, m.selected().level());
        in.key(KeyEvent.VK_C, 'c');
        assertTrue(m.selected().cage());
        assertFalse(in.key(KeyEvent.VK_Q, 'q'));

        // The fit depends on the direction (the box as seen from it), which the arrow key turned:
        // F from here, then zoomed away and F again, comes back to the same distance.
        m.zoom(3);
        in.key(KeyEvent.VK_F, 'f');
        double fitted = m.camera().distance();
        assertNotEquals(d / 3, fitted, 1e-9, "F undoes the zoom");
        m.zoom(0.25);
        in.key(KeyEvent.VK_F, 'f');
        assertEquals(fitted, m.camera().distance(), 1e-9, "F fits again");

        var target = m.camera().target();
        double pitch = m.camera().pitch();
        in.press(100, 100, false);
        in.drag(100, 130);
        in.release();
        assertTrue(m.camera().pitch() > pitch, "left drag orbits");
        assertEquals(target, m.camera().target());
        in.press(100, 100, true);
        in.drag(150, 100);
        in.release();
        assertNotEquals(target, m.camera().target(), "right or shift drag pans");
        in.drag(300, 300);
        double before = m.camera().distance();
        in.wheel(1);
        assertTrue(m.camera().distance() > before, "wheel towards the user zooms out");
        assertEquals(List.of(), errors);
    }
}
