package lt.spindulys.plugin.obj;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.io.ObjWriter;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.OutputPlugins;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;

class ObjExportPluginTest {
    @TempDir Path dir;

    private static final PluginView VIEW = new PluginView(new Vec3(0, 0, 5), new Vec3(0, 0, 0), new Vec3(0, 1, 0), 45, 64, 48);
    private final ObjExportPlugin plugin = new ObjExportPlugin();

    private static ControlMesh shape(String file) {
        try (InputStream in = new GZIPInputStream(ObjExportPluginTest.class.getClassLoader().getResourceAsStream("subdiv/" + file))) {
            return ObjReader.parseSubdiv(new String(in.readAllBytes(), StandardCharsets.US_ASCII), file).toControlMesh();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** A crease cube with uvs at level 2, an open grid with holes at level 1, and a chaikin shape shown as its cage. */
    private static List<DisplayedSurface> surfaces() {
        return List.of(
                new DisplayedSurface("cube.obj", shape("catmark_cube_creases1.obj.gz"), DisplayedSurface.Scheme.CATMULL_CLARK, 2),
                new DisplayedSurface("holes", shape("catmark_hole_test1.obj.gz"), DisplayedSurface.Scheme.CATMULL_CLARK, 1),
                new DisplayedSurface("chaikin shape", shape("catmark_chaikin1.obj.gz"), DisplayedSurface.Scheme.NONE, 0));
    }

    private PluginResult run(List<DisplayedSurface> surfaces, Map<String, String> options, Path out, PluginProgress progress)
            throws IOException, InterruptedException {
        return plugin.run(new PluginRequest(surfaces, VIEW, options, out, progress));
    }

    /** The text {@link ObjWriter} makes of a control mesh: equal texts mean equal meshes, tags and options, bit for bit. */
    private static String text(ControlMesh m) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ObjWriter.write(m, null, null, out);
        return out.toString(StandardCharsets.UTF_8);
    }

    private List<String> files() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void serviceLoaderFindsIt() {
        assertTrue(OutputPlugins.available().stream().anyMatch(p -> p instanceof ObjExportPlugin), "OutputPlugins.available()");
        assertTrue(ServiceLoader.load(OutputPlugin.class).stream().anyMatch(p -> p.type() == ObjExportPlugin.class), "ServiceLoader");
        OutputPlugin p = OutputPlugins.find("obj").orElseThrow();
        assertEquals("OBJ export", p.name());
        assertEquals(List.of("obj"), p.fileExtensions());
        assertFalse(p.description().isBlank());
    }

    @Test
    void optionsAreTheExportChoiceAndOneSwitchPerSurface() {
        List<PluginOption> o = plugin.options(surfaces(), VIEW);
        assertEquals(List.of("export", "surface.0.export", "surface.1.export", "surface.2.export"), o.stream().map(PluginOption::key).toList());
        assertEquals(List.of(ObjExportPlugin.CONTROL, ObjExportPlugin.REFINED, ObjExportPlugin.LIMIT), o.get(0).choices());
        assertEquals(ObjExportPlugin.CONTROL, o.get(0).defaultValue());
        assertEquals("holes", o.get(2).group());
        assertEquals(PluginOption.Kind.BOOLEAN, o.get(2).kind());
    }

    @Test
    void oneControlMeshGoesToTheChosenFileAndReadsBackEqual() throws Exception {
        DisplayedSurface cube = surfaces().get(0);
        Path out = dir.resolve("cube-export.obj");
        List<Double> fractions = new ArrayList<>();
        PluginProgress progress = new PluginProgress() {
            @Override public void progress(double fraction, String stage) { fractions.add(fraction); }
            @Override public boolean isCancelled() { return false; }
        };
        PluginResult r = run(List.of(cube), Map.of(), out, progress);
        assertEquals(List.of(out), r.files());
        assertEquals("control mesh with tags, 8 vertices, 6 faces", r.summary());
        assertEquals(List.of("cube-export.obj"), files());
        String written = Files.readString(out);
        assertTrue(written.contains("\no cube.obj\n") && written.contains("\nt crease 2/1/0 "), "object name and tags");
        ControlMesh back = ObjReader.readSubdiv(out).toControlMesh();
        assertEquals(text(cube.control()), text(back));
        assertTrue(cube.control().tags().creaseCount() > 0 && cube.control().uvs() != null, "the test shape has creases and uvs");
        assertEquals(1.0, fractions.get(fractions.size() - 1));
        for (int i = 1; i < fractions.size(); i++) assertTrue(fractions.get(i) >= fractions.get(i - 1), "progress never goes back");
    }

    @Test
    void severalControlMeshesGoOnePerFileBesideTheChosenOne() throws Exception {
        List<DisplayedSurface> s = surfaces();
        Path out = dir.resolve("scene.obj");
        PluginResult r = run(s, Map.of("export", "control mesh"), out, PluginProgress.NONE);
        List<Path> expected = List.of(dir.resolve("scene-cube.obj"), dir.resolve("scene-holes.obj"), dir.resolve("scene-chaikin_shape.obj"));
        assertEquals(expected, r.files());
        assertEquals(List.of("scene-chaikin_shape.obj", "scene-cube.obj", "scene-holes.obj"), files(), "the chosen file itself is not written");
        for (int i = 0; i < s.size(); i++) {
            ControlMesh back = ObjReader.readSubdiv(expected.get(i)).toControlMesh();
            assertEquals(text(s.get(i).control()), text(back), s.get(i).name());
        }
        assertTrue(r.summary().startsWith("3 control meshes with tags in 3 files, "), r.summary());
    }

    @Test
    void refinedSurfacesShareOneFileAsObjects() throws Exception {
        List<DisplayedSurface> s = surfaces();
        Path out = dir.resolve("refined.obj");
        PluginResult r = run(s, Map.of("export", "refined"), out, PluginProgress.NONE);
        assertEquals(List.of(out), r.files());
        String written = Files.readString(out);
        assertTrue(written.contains("\no cube.obj\n") && written.contains("\no holes\n") && written.contains("\no chaikin shape\n"), "one object per surface");
        assertFalse(written.contains("\nvn "), "no normals off the limit surface");
        assertFalse(written.contains("\nt "), "no tags on a refined mesh");
        MeshData m = ObjReader.read(out);
        List<RefinedMesh> refined = List.of(CatmullClark.refine(s.get(0).control(), 2), CatmullClark.refine(s.get(1).control(), 1),
                CatmullClark.refine(s.get(2).control(), 0));
        assertSurfaces(refined, false, m);
        assertTrue(refined.get(1).hasHoles(), "the hole shape's holes are left out");
    }

    @Test
    void limitSurfacesHaveLimitPositionsAndNormals() throws Exception {
        List<DisplayedSurface> s = surfaces();
        Path out = dir.resolve("limit.obj");
        run(s, Map.of("export", "limit surface", "surface.2.export", "false"), out, PluginProgress.NONE);
        MeshData m = ObjReader.read(out);
        List<RefinedMesh> refined = List.of(CatmullClark.refine(s.get(0).control(), 2), CatmullClark.refine(s.get(1).control(), 1));
        assertSurfaces(refined, true, m);
        assertFalse(Files.readString(out).contains("\no chaikin shape\n"), "the surface switched off is not written");
    }

    /** The file holds these meshes one after another: positions (or limit positions and normals), uvs and every face that is not a hole. */
    private static void assertSurfaces(List<RefinedMesh> meshes, boolean limit, MeshData m) {
        int v = 0, t = 0, corner = 0, face = 0;
        for (RefinedMesh r : meshes) {
            double[] p = limit ? r.limitPositions() : r.positions();
            for (int i = 0; i < p.length; i++) assertEquals(p[i], m.positions()[3 * v + i], "position " + i);
            if (limit) for (int i = 0; i < p.length; i++) assertEquals(r.limitNormals()[i], m.normals()[3 * v + i], "normal " + i);
            int[] sizes = r.faceSizes(), fv = r.faceVertices();
            for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
                if (r.isHole(f)) continue;
                assertEquals(sizes[f], m.faceSizes()[face++]);
                for (int j = 0; j < sizes[f]; j++, corner++) {
                    assertEquals(fv[c + j] + v, m.vertexIndex()[corner]);
                    if (limit) assertEquals(fv[c + j] + v, m.normalIndex()[corner]);
                    if (r.uvs() != null) {
                        int uv = m.uvIndex()[corner];
                        assertEquals(r.faceUvs()[c + j] + t, uv);
                        assertEquals(r.uvs()[2 * (uv - t)], m.uvs()[2 * uv]);
                    }
                }
            }
            v += r.vertexCount();
            if (r.uvs() != null) t += r.uvs().length / 2;
        }
        assertEquals(v, m.vertexCount(), "vertices");
        assertEquals(face, m.faceCount(), "faces");
    }

    @Test
    void cancelWritesNothingAndKeepsAnOldFile() throws Exception {
        Path out = dir.resolve("out.obj");
        Files.writeString(out, "old\n");
        for (String mode : List.of("control mesh", "refined", "limit surface")) {
            for (int after : new int[] {0, 1, 3}) {
                AtomicInteger calls = new AtomicInteger();
                PluginProgress cancelling = new PluginProgress() {
                    @Override public void progress(double fraction, String stage) { }
                    @Override public boolean isCancelled() { return calls.getAndIncrement() >= after; }
                };
                assertThrows(CancellationException.class, () -> run(surfaces(), Map.of("export", mode), out, cancelling), mode + " " + after);
                assertEquals(List.of("out.obj"), files(), "no new file, no temporary left: " + mode + " " + after);
                assertEquals("old\n", Files.readString(out));
            }
        }
    }

    @Test
    void anInterruptWritesNothing() throws Exception {
        Path out = dir.resolve("out.obj");
        Thread.currentThread().interrupt();
        try {
            assertThrows(InterruptedException.class, () -> run(surfaces(), Map.of("export", "refined"), out, PluginProgress.NONE));
        } finally {
            Thread.interrupted();
        }
        assertEquals(List.of(), files());
    }

    @Test
    void anUnwritablePathFailsWithOneLineAndNoFile() {
        Path missing = dir.resolve("no-such-folder").resolve("out.obj");
        IOException e = assertThrows(IOException.class, () -> run(surfaces(), Map.of(), missing, PluginProgress.NONE));
        assertEquals("cannot write '" + missing + "': directory '" + missing.getParent() + "' does not exist", e.getMessage());
        assertFalse(Files.exists(missing.getParent()));

        // /proc takes no new files, even from root.
        Path proc = Path.of("/proc/spindulys-obj-export-test.obj");
        if (Files.isDirectory(proc.getParent())) {
            IOException p = assertThrows(IOException.class, () -> run(surfaces(), Map.of("export", "refined"), proc, PluginProgress.NONE));
            assertTrue(p.getMessage().startsWith("cannot write '" + proc + "': cannot create a file in '/proc': "), p.getMessage());
            assertFalse(p.getMessage().contains("\n"));
            assertFalse(Files.exists(proc));
        }
    }

    @Test
    void badOptionsAreOneLineNamingTheOption() {
        Path out = dir.resolve("out.obj");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> run(surfaces(), Map.of("export", "mesh"), out, PluginProgress.NONE));
        assertEquals("Export (export) must be one of control mesh, refined, limit surface, found 'mesh'", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> run(surfaces(), Map.of("colour", "red"), out, PluginProgress.NONE));
        assertTrue(e.getMessage().startsWith("unknown option 'colour'"), e.getMessage());
        Map<String, String> none = new HashMap<>();
        for (int i = 0; i < 3; i++) none.put("surface." + i + ".export", "false");
        e = assertThrows(IllegalArgumentException.class, () -> run(surfaces(), none, out, PluginProgress.NONE));
        assertEquals("no surface is chosen for export (every surface's Export option is false)", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> run(surfaces(), Map.of(), dir.resolve("out.png"), PluginProgress.NONE));
        assertEquals("the output file '" + dir.resolve("out.png") + "' must end in .obj", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> run(surfaces(), Map.of(), dir.resolve("noext"), PluginProgress.NONE));
    }

    @Test
    void aNumberAnObjFileCannotHoldFailsWithoutAFile() throws Exception {
        ControlMesh far = ControlMesh.builder(new double[] {0, 0, 0, 1, 0, 0, 1, 2e15, 0}, new int[] {3}, new int[] {0, 1, 2}).source("far").build();
        Path out = dir.resolve("far.obj");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> run(List.of(new DisplayedSurface("far", far, DisplayedSurface.Scheme.NONE, 0)), Map.of(), out, PluginProgress.NONE));
        assertEquals("far: vertex 2 has the number 2.0E15, beyond the 1e15 an OBJ file may hold", e.getMessage());
        assertEquals(List.of(), files());
    }

    @Test
    void aLevelTheHeapCannotHoldIsRefusedBeforeRefining() throws Exception {
        // The cube at level 8: 393,216 faces, 176 bytes each (+64 on the limit surface), against a 16 MiB budget.
        DisplayedSurface deep = new DisplayedSurface("deep cube", shape("catmark_cube.obj.gz"), DisplayedSurface.Scheme.CATMULL_CLARK, 8);
        Path out = dir.resolve("deep.obj");
        try (HeapBudget.Scope cap = HeapBudget.cap(16L << 20)) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> run(List.of(deep), Map.of("export", "limit surface"), out, PluginProgress.NONE));
            assertTrue(e.getMessage().startsWith("surface deep cube: subdivision level 8 of this mesh (393216 faces;"), e.getMessage());
            assertFalse(e.getMessage().contains("\n"));
            // The control mesh needs no refining: it is written under the same budget.
            run(List.of(deep), Map.of(), out, PluginProgress.NONE);
        }
        assertEquals(List.of("deep.obj"), files());
    }

    @Test
    void theDocsExampleSaysWhatItWrote() throws Exception {
        // docs/plugins.md: a cube at level 3 on the limit surface.
        DisplayedSurface cube = new DisplayedSurface("cube", shape("catmark_cube.obj.gz"), DisplayedSurface.Scheme.CATMULL_CLARK, 3);
        PluginResult r = OutputPlugins.find("obj").orElseThrow().run(new PluginRequest(List.of(cube), VIEW, Map.of("export", "limit surface"),
                dir.resolve("cube-limit.obj"), PluginProgress.NONE));
        assertEquals("limit surface, 386 vertices, 384 faces", r.summary());
    }

    @Test
    void siblingNamesAreSafeAndDistinct() {
        ControlMesh m = surfaces().get(0).control();
        List<DisplayedSurface> s = List.of(new DisplayedSurface("cube.obj", m, DisplayedSurface.Scheme.NONE, 0),
                new DisplayedSurface("Cube.OBJ", m, DisplayedSurface.Scheme.NONE, 0),
                new DisplayedSurface("a/b:c", m, DisplayedSurface.Scheme.NONE, 0),
                new DisplayedSurface("..", m, DisplayedSurface.Scheme.NONE, 0),
                new DisplayedSurface("šuo.dat", m, DisplayedSurface.Scheme.NONE, 0));
        Path out = Path.of("x", "out.obj");
        assertEquals(List.of(Path.of("x", "out-cube.obj"), Path.of("x", "out-Cube-2.obj"), Path.of("x", "out-a_b_c.obj"),
                Path.of("x", "out-surface3.obj"), Path.of("x", "out-šuo.obj")), ObjExportPlugin.siblings(out, s, List.of(0, 1, 2, 3, 4)));
    }
}
