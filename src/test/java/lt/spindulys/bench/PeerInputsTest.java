package lt.spindulys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.io.SceneParser;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;

/** The peers' inputs for a view, and the view read from our scene files. */
class PeerInputsTest {
    private static final PeerView VIEW = new PeerView(new Vec3(0, 2.5, 3.5), new Vec3(0, -0.2, 0), new Vec3(0, 1, 0), 40, 1280, 720,
            new Vec3(3, 5, 2), 79.6, List.of(Path.of("/m/torus.obj"), Path.of("/m/ground.obj")));

    @Test
    void embreeCommandLineAsThePeerKitsProtocol() {
        assertEquals("pathtracer -i /m/torus.obj -i /m/ground.obj --vp 0 2.5 3.5 --vi 0 -0.2 0 --vu 0 1 0 --fov 40 --righthanded "
                + "--size 1280 720 --pointlight 3 5 2 79.6 79.6 79.6 --spp 1 --max-path-length 1 --threads 2 --benchmark 1 10 --legacy",
                String.join(" ", PeerInputs.embree("pathtracer", VIEW, 2, List.of("--benchmark", "1", "10", "--legacy"))));
    }

    @Test
    void cyclesCommandLineAndScript(@TempDir Path dir) throws IOException {
        Path script = PeerInputs.writeCyclesScript(dir);
        String py = Files.readString(script);
        assertTrue(py.contains("bpy.ops.render.render(write_still=True)"));
        // 4 pi x 79.6 W/sr = 1000.28 W
        assertEquals("blender -b --factory-startup -noaudio -P " + script + " -- --mesh /m/torus.obj --mesh /m/ground.obj --image /o/x.tga "
                + "--threads 2 --size 1280 720 --eye 0 2.5 3.5 --at 0 -0.2 0 --vfov 40 --light 3 5 2 --watts 1000.283101",
                String.join(" ", PeerInputs.cycles("blender", script, VIEW, 2, Path.of("/o/x.tga"))));
    }

    @Test
    void povSceneHasTheViewAndTheIncludes() {
        String pov = PeerInputs.povScene(VIEW, List.of("torus.inc", "ground.inc"));
        assertTrue(pov.contains("location <0,2.5,3.5>\n  right -x*1280/720\n  up y\n  angle 65.8104\n  look_at <0,-0.2,0>"), pov);
        // 79.6 / (2 pi)
        assertTrue(pov.contains("light_source { <3,5,2> color rgb 12.668733 fade_distance 1 fade_power 2 }"), pov);
        assertTrue(pov.contains("#include \"torus.inc\"\n  texture { BenchGrey } }\nobject {\n#include \"ground.inc\""), pov);
        assertTrue(pov.contains("max_trace_level 1"));
        assertEquals(List.of("povray", "+Iview.pov", "+Ox.ppm", "+W1280", "+H720", "-A", "+WT2", "-D", "+FP", "-V"),
                PeerInputs.povray("povray", VIEW, 2, "view.pov", "x.ppm"));
    }

    /** Quads are split along v0-v2 (fanned from the first corner), indices from 0. */
    @Test
    void mesh2OfATinyMesh() throws IOException {
        MeshData m = ObjReader.parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 -0.5\nv 2 0 0.333333\nf 1 2 3 4\nf 2 5 3\n", "tiny.obj");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        PeerInputs.writeMesh2(out, m);
        assertEquals("""
                mesh2 {
                 vertex_vectors { 5,
                <0,0,0>,
                <1,0,0>,
                <1,1,0>,
                <0,1,-0.5>,
                <2,0,0.333333>
                 }
                 face_indices { 3,
                <0,1,2>,
                <0,2,3>,
                <1,4,2>
                 }
                }
                """, out.toString(StandardCharsets.US_ASCII));
    }

    @Test
    void viewIsReadFromOurScene() throws IOException {
        String scene = """
                settings { width 1280 height 720 samples 1 }
                camera { eye 0 3.3 1.5  lookat 0 -0.1 0.1  up 0 1 0  fov 40 }
                light { position 3 5 2  color 1 1 1  intensity 25.3375  falloff inverse-square }
                """;
        PeerView v = PeerView.of(SceneParser.parse(scene, "v.dat", Path.of(".")), List.of(Path.of("a.obj")));
        assertEquals(new Vec3(0, 3.3, 1.5), v.eye());
        assertEquals(new Vec3(0, -0.1, 0.1), v.at());
        assertEquals(40, v.verticalFov());
        assertEquals(79.6001, v.radiantIntensity(), 1e-4);
        assertEquals(65.8104, v.horizontalFov(), 1e-4);
        IOException e = assertThrows(IOException.class, () -> PeerView.of(SceneParser.parse(
                scene.replace("falloff inverse-square", ""), "v.dat", Path.of(".")), List.of()));
        assertTrue(e.getMessage().contains("inverse-square"));
    }

    /** A rectangle light becomes a 4x4 jittered, non-adaptive area_light with its full edges as axes. */
    @Test
    void povSceneOfARectangleLight() throws IOException {
        String scene = """
                settings { width 1280 height 720 samples 16 }
                camera { eye 0 2.5 3.5  lookat 0 -0.2 0  up 0 1 0  fov 40 }
                rectlight { center 1.5 4 -1.5  normal 0 -1 0  tangent 1 0 0  width 3  height 2  intensity 2.2  onesided true  samples 1 }
                """;
        PeerView v = PeerView.ofArea(SceneParser.parse(scene, "s.dat", Path.of(".")), List.of(Path.of("a.obj")));
        // 2.2 x 6 x pi W/sr straight below; / (2 pi) = 6.6
        assertEquals(2.2 * 6 * Math.PI, v.radiantIntensity(), 1e-9);
        String pov = PeerInputs.povScene(v, List.of("a.inc"));
        assertTrue(pov.contains("light_source { <1.5,4,-1.5> color rgb 6.6\n  area_light <3,0,0>, <0,0,2>, 4, 4 adaptive 0 jitter area_illumination on\n  "
                + "fade_distance 1 fade_power 2 }"), pov);
        assertFalse(pov.contains("circular"), pov);
    }

    /** A disc light becomes a circular area_light whose axes are two diameters; the grid is the square root of the samples. */
    @Test
    void povSceneOfADiscLight() throws IOException {
        String scene = """
                settings { width 640 height 360 samples 9 }
                camera { eye 0 2.5 3.5  lookat 0 -0.2 0  up 0 1 0  fov 40 }
                disclight { center 0 4 0  normal 0 -1 0  radius 0.5  intensity 4  samples 1 }
                """;
        PeerView v = PeerView.ofArea(SceneParser.parse(scene, "s.dat", Path.of(".")), List.of());
        assertEquals(3, v.area().grid());
        assertTrue(v.area().disc());
        assertEquals(1, v.area().axis1().length(), 1e-12);
        assertEquals(1, v.area().axis2().length(), 1e-12);
        assertEquals(0, v.area().axis1().dot(v.area().axis2()), 1e-12);
        assertEquals(0, v.area().axis1().dot(new Vec3(0, 1, 0)), 1e-12);
        String pov = PeerInputs.povScene(v, List.of());
        // 4 x pi 0.25 x pi / (2 pi) = pi / 2
        assertTrue(pov.contains("light_source { <0,4,0> color rgb 1.570796\n  area_light <"), pov);
        assertTrue(pov.contains(">, 3, 3 adaptive 0 jitter circular area_illumination on\n  fade_distance 1 fade_power 2 }"), pov);
        // Point-light views keep their one-line light_source.
        assertFalse(PeerInputs.povScene(VIEW, List.of()).contains("area_light"));
    }

    /** A soft-shadow view needs one white rect or disc light, no point light, and a square number of shadow rays per pixel. */
    @Test
    void softShadowViewRefusesOtherScenes() {
        String base = """
                settings { width 640 height 360 samples 16 }
                camera { eye 0 2.5 3.5  lookat 0 -0.2 0  up 0 1 0  fov 40 }
                """;
        String disc = "disclight { center 0 4 0  normal 0 -1 0  radius 0.5  intensity 4  samples 1 }\n";
        for (String[] bad : new String[][] {
                {base.replace("samples 16", "samples 8") + disc, "square number of shadow rays per pixel, found 8"},
                {base + disc.replace("samples 1", "samples 2"), "square number of shadow rays per pixel, found 32"},
                {base + "spherelight { center 0 4 0  radius 0.5  intensity 4 }\n", "rectangle or disc"},
                {base + disc + "light { position 3 5 2  falloff inverse-square }\n", "no point light"},
                {base, "exactly one area light"}}) {
            IOException e = assertThrows(IOException.class, () -> PeerView.ofArea(SceneParser.parse(bad[0], "s.dat", Path.of(".")), List.of()));
            assertTrue(e.getMessage().contains(bad[1]), e.getMessage());
        }
    }

    /** The bench scenes the peers are run on name the meshes the bench gives the peers, and have views the peers can take. */
    @Test
    void benchScenesNameTheirMeshes() throws IOException {
        for (String[] s : new String[][] {{"knot-1m", "knot_1m.obj"}, {"torus-1m-close", "torus_1m.obj"}, {"torus-1m", "torus_1m.obj"}}) {
            String text = Files.readString(Path.of("scenes", "bench", s[0] + ".dat"));
            assertTrue(text.contains("mesh { file \"meshes/" + s[1] + "\""), s[0]);
            assertTrue(text.contains("mesh { file \"meshes/ground.obj\""), s[0]);
            String noMeshes = text.replaceAll("(?m)^mesh .*$", "");
            PeerView.of(SceneParser.parse(noMeshes, s[0] + ".dat", Path.of(".")), List.of());
        }
        String soft = Files.readString(Path.of("scenes", "bench", "soft-shadow.dat"));
        assertTrue(soft.contains("mesh { file \"meshes/torus_1k.obj\""));
        assertTrue(soft.contains("mesh { file \"meshes/ground.obj\""));
        PeerView v = PeerView.ofArea(SceneParser.parse(soft.replaceAll("(?m)^mesh .*$", ""), "soft-shadow.dat", Path.of(".")), List.of());
        assertEquals(4, v.area().grid());
        // The equal-rays twin: 1 sample per pixel, 16 light samples, the same 4x4 grid.
        String light16 = Files.readString(Path.of("scenes", "bench", "soft-shadow-light16.dat"));
        assertEquals(soft.replace("samples 16", "samples 1").replace("samples 1 }", "samples 16 }").replaceAll("(?m)^#.*\\n", ""),
                light16.replaceAll("(?m)^#.*\\n", ""));
        assertEquals(4, PeerView.ofArea(SceneParser.parse(light16.replaceAll("(?m)^mesh .*$", ""), "l.dat", Path.of(".")), List.of()).area().grid());
    }

    @Test
    void peersOption() throws BenchUsageException {
        assertEquals(EnumSet.of(PeerBench.Peer.EMBREE, PeerBench.Peer.CYCLES), PeerBench.Peer.parse("embree,cycles"));
        assertEquals(EnumSet.noneOf(PeerBench.Peer.class), PeerBench.Peer.parse("none"));
        BenchUsageException e = assertThrows(BenchUsageException.class, () -> PeerBench.Peer.parse("embree,sunflow"));
        assertEquals("unknown peer 'sunflow' in --peers (expected embree, povray, cycles or none)", e.getMessage());
    }

    @Test
    void medianOfPairRatiosSkipsFailedPairs() {
        assertEquals(2.0, PeerBench.medianRatio(new double[] {2, 6, 3, Double.NaN}, new double[] {1, 2, 2, 1}), 1e-12);
        assertTrue(Double.isNaN(PeerBench.medianRatio(new double[] {Double.NaN}, new double[] {1})));
    }
}
