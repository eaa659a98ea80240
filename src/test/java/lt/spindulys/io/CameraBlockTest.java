package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.AnimatedCamera;
import lt.spindulys.camera.Camera;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.files.AtomicFile;
import lt.spindulys.math.Vec3;

/** A camera written as a block reads back as the same camera; the block is found and replaced with nothing else in the file changed. */
class CameraBlockTest {
    @TempDir Path dir;

    private static Camera read(String text) {
        return SceneParser.parse(text, "t.dat", null).camera();
    }

    private static void assertSameView(PinholeCamera a, PinholeCamera b) {
        assertEquals(a.eye(), b.eye());
        assertEquals(a.lookAt(), b.lookAt());
        assertEquals(a.up(), b.up());
        assertEquals(a.fovDegrees(), b.fovDegrees());
    }

    @Test
    void aPinholeReadsBackExactly() {
        PinholeCamera c = new PinholeCamera(new Vec3(0.1 + 0.2, -1e-7, 3.4641016151377544), new Vec3(0, 1, 0), new Vec3(0, 0, 1), 37.5);
        String block = CameraBlock.format(c, null);
        assertEquals("camera { eye 0.30000000000000004 -1.0E-7 3.4641016151377544  lookat 0 1 0  up 0 0 1  fov 37.5 }", block);
        assertSameView(c, (PinholeCamera) read(block));
    }

    @Test
    void aThinLensKeepsItsLensAndLeavesOutTheDefaultFocus() {
        PinholeCamera view = new PinholeCamera(new Vec3(1, 2, -3), new Vec3(0, 0.5, 0), Vec3.Y, 40);
        ThinLensCamera onLookAt = new ThinLensCamera(view, 0.12);
        String block = CameraBlock.format(onLookAt, null);
        assertFalse(block.contains("focus"), block);
        ThinLensCamera back = (ThinLensCamera) read(block);
        assertSameView(view, back.view());
        assertEquals(0.12, back.aperture());
        assertEquals(onLookAt.focusDistance(), back.focusDistance());

        ThinLensCamera ring = new ThinLensCamera(view, 0.3, 2.75, LensPattern.RING);
        ThinLensCamera r = (ThinLensCamera) read(CameraBlock.format(ring, null));
        assertEquals(2.75, r.focusDistance());
        assertEquals(LensPattern.RING, r.lensPattern());
    }

    @Test
    void anOrthographicViewKeepsItsWidth() {
        OrthographicCamera o = new OrthographicCamera(new Vec3(4, 3, -4), new Vec3(0, 0.5, 0), Vec3.Y, 5.25);
        String block = CameraBlock.format(o, null);
        assertTrue(block.endsWith("projection orthographic  width 5.25 }"), block);
        OrthographicCamera back = (OrthographicCamera) read(block);
        assertEquals(o.eye(), back.eye());
        assertEquals(5.25, back.viewWidth());
    }

    @Test
    void anAnimatedCameraIsWrittenWithTheFilesKeysText() {
        String text = "animation { frames 1 4 }\ncamera { eye 0 2 -8  lookat 0 0 0\n  turntable { turns 2 } # around\n}\n";
        CameraBlock.Located l = CameraBlock.locate(text, "t.dat");
        assertEquals("turntable { turns 2 }", l.keysText());
        AnimatedCamera a = (AnimatedCamera) read(text);
        Camera moved = a.withBase(new PinholeCamera(new Vec3(1, 2, -8), Vec3.ZERO, Vec3.Y, 45));
        String block = CameraBlock.format(moved, l.keysText());
        assertEquals("camera { eye 1 2 -8  lookat 0 0 0  up 0 1 0  fov 45  turntable { turns 2 } }", block);
        AnimatedCamera back = (AnimatedCamera) read("animation { frames 1 4 }\n" + block);
        assertEquals(new Vec3(1, 2, -8), ((PinholeCamera) back.base()).eye());
        assertThrows(IllegalArgumentException.class, () -> CameraBlock.format(moved, null));
    }

    @Test
    void locateFindsTheStatementNotTheWordElsewhere() {
        String text = "# camera { in a comment }\nmaterial camera { color 1 0 0 }\ntexture camera2 { type checker }\n"
                + "mesh { file \"camera {.obj\" }\n  camera{eye 0 0 -5 lookat 0 0 0}  sphere { radius 1 material camera }\n";
        CameraBlock.Located l = CameraBlock.locate(text, "t.dat");
        assertEquals("camera{eye 0 0 -5 lookat 0 0 0}", text.substring(l.start(), l.end()));
        assertEquals(5, l.line());
        assertEquals(3, l.column());
        assertNull(l.keysText());
        assertEquals("camera { eye 0 0 -5 lookat 0 0 0 }", l.tokens());
        assertEquals(l.tokens(), CameraBlock.locate("camera {\n eye 0 0 -5 # here\n lookat 0 0 0 }", "t.dat").tokens(),
                "spacing and comments do not change the tokens");
        assertNull(CameraBlock.locate("sphere { radius 1 }", "t.dat"));
    }

    @Test
    void locateRefusesTwoCamerasAndUnclosedBlocksAtTheirPlace() {
        SceneException two = assertThrows(SceneException.class,
                () -> CameraBlock.locate("camera { eye 0 0 -5 lookat 0 0 0 }\ncamera { eye 0 0 -5 lookat 0 0 0 }", "s.dat"));
        assertEquals("s.dat:2:1: camera is already defined at 1:1", two.getMessage());
        SceneException open = assertThrows(SceneException.class, () -> CameraBlock.locate("sphere {\n camera { eye", "s.dat"));
        assertEquals("s.dat:1:8: this '{' of 'sphere' is never closed", open.getMessage());
    }

    @Test
    void replaceKeepsEveryOtherCharacter() {
        String text = "\uFEFF# Šviesa\r\nsettings { width 4 }\r\ncamera { eye 0 0 -5\r\n lookat 0 0 0 } # kept\r\nsphere { radius 1 }\r\n";
        String block = "camera { eye 1 1 -5  lookat 0 0 0  up 0 1 0  fov 45 }";
        String out = CameraBlock.replace(text, "t.dat", block);
        assertEquals("\uFEFF# Šviesa\r\nsettings { width 4 }\r\n" + block + " # kept\r\nsphere { radius 1 }\r\n", out);
        // Without a camera statement, the block goes on a line of its own before the first statement.
        assertEquals("# head\n" + block + "\nsphere { radius 1 }\n", CameraBlock.replace("# head\nsphere { radius 1 }\n", "t.dat", block));
        assertEquals(block + "\n", CameraBlock.replace("", "t.dat", block));
    }

    @Test
    void saveRewritesOnlyTheBlockAtomically() throws Exception {
        String head = "# Ąžuolas \u00e9\nsettings { width 4  height 3 }\n", tail = "   # after\nsphere { radius 1 }\n\n";
        Path f = dir.resolve("scene.dat");
        Files.write(f, (head + "camera { eye 0 0 -5 lookat 0 0 0 }" + tail).getBytes(StandardCharsets.UTF_8));
        PinholeCamera c = new PinholeCamera(new Vec3(-2.5, 1, -4), Vec3.ZERO, Vec3.Y, 30);
        String block = CameraBlock.save(f, c);
        byte[] expected = (head + block + tail).getBytes(StandardCharsets.UTF_8);
        assertArrayEquals(expected, Files.readAllBytes(f));
        assertSameView(c, (PinholeCamera) SceneParser.parse(f).camera());
        try (var files = Files.list(dir)) {
            assertEquals(1, files.filter(p -> !AtomicFile.isTemporaryName(p.getFileName().toString())).count());
        }
        try (var files = Files.list(dir)) {
            assertEquals(0, files.filter(p -> AtomicFile.isTemporaryName(p.getFileName().toString())).count(), "no temporary file is left");
        }
    }

    @Test
    void saveThroughALinkReplacesTheFileItLeadsTo() throws Exception {
        Path real = dir.resolve("real.dat"), link = dir.resolve("link.dat");
        Files.writeString(real, "camera { eye 0 0 -5 lookat 0 0 0 }\n");
        Files.createSymbolicLink(link, real.getFileName());
        CameraBlock.save(link, new PinholeCamera(new Vec3(0, 0, -6), Vec3.ZERO, Vec3.Y, 45));
        assertTrue(Files.isSymbolicLink(link));
        assertEquals("camera { eye 0 0 -6  lookat 0 0 0  up 0 1 0  fov 45 }\n", Files.readString(real));
    }

    @Test
    void aSceneFileIsToldFromAWorkframeMesh() throws Exception {
        Path scene = dir.resolve("s.dat"), mesh = dir.resolve("m.dat"), empty = dir.resolve("e.dat");
        Files.writeString(scene, "\uFEFF# a scene\n\n  camera { eye 0 0 -5 lookat 0 0 0 }\n");
        Files.writeString(mesh, "# a mesh\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        Files.writeString(empty, "# nothing yet\n");
        assertTrue(SceneParser.isSceneFile(scene));
        assertFalse(SceneParser.isSceneFile(mesh));
        assertTrue(SceneParser.isSceneFile(empty));
        assertFalse(SceneParser.isSceneFile(Path.of("scenes/models/cube.dat")));
        assertTrue(SceneParser.isSceneFile(Path.of("scenes/spheres.dat")));
    }
}
