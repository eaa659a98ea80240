package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.render.RenderJob;
import lt.spindulys.scene.InputFile;
import lt.spindulys.scene.SceneBuilder;

/** {@link AssetRoots} through the library's API: the parser and a render job confine reads and record what they read. */
class AssetRootsTest {
    @TempDir Path dir;

    @Test
    void insideIsAllowedOutsideAndThroughLinksOutIsNot() throws IOException {
        Path job = Files.createDirectories(dir.resolve("job"));
        Path out = Files.writeString(dir.resolve("x.obj"), "v 0 0 0\n");
        AssetRoots roots = AssetRoots.of(List.of(job));
        assertTrue(roots.confines());
        assertTrue(roots.allows(job.resolve("a/b.obj")));
        assertFalse(roots.allows(job.resolve("../x.obj")));
        assertFalse(roots.allows(out));
        Path link = Files.createSymbolicLink(job.resolve("l.obj"), out);
        assertEquals("is outside the allowed asset folders (" + job.toRealPath() + "): it resolves to " + out.toRealPath(), roots.refusal(link));
        assertNull(AssetRoots.ANY.refusal(out));
        assertFalse(AssetRoots.ANY.confines());
        // Folders of a list, and two confinements together.
        AssetRoots both = AssetRoots.parse(dir + File.pathSeparator + File.pathSeparator + job);
        assertTrue(both.allows(out));
        assertFalse(both.and(roots).allows(out));
        assertTrue(both.and(roots).allows(job.resolve("y.obj")));
        assertSame(roots, roots.and(AssetRoots.ANY));
        assertSame(AssetRoots.ANY, AssetRoots.parse(" "));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> AssetRoots.of(List.of(out)));
        assertEquals("asset folder '" + out + "' is not a folder", e.getMessage());
    }

    @Test
    void theParserRefusesAFileOutsideAtItsKeyAndRecordsWhatItRead() throws IOException {
        Path job = Files.createDirectories(dir.resolve("job"));
        Files.writeString(dir.resolve("m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Files.copy(dir.resolve("m.obj"), job.resolve("m.obj"));
        Path scene = Files.writeString(job.resolve("s.dat"), "camera { eye 0 0 -5 lookat 0 0 0 }\nmesh { file \"../m.obj\" }\n");
        AssetRoots roots = AssetRoots.of(List.of(job));
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse(scene, roots));
        assertEquals(scene + ":2:13: mesh file '../m.obj' is outside the allowed asset folders (" + job.toRealPath() + ")", e.getMessage());
        // Without a confinement it reads, and records, both files.
        SceneBuilder b = SceneParser.parse(scene);
        assertEquals(List.of(new InputFile(scene, "scene file", null), new InputFile(dir.resolve("m.obj").toAbsolutePath().normalize(), "mesh file", scene + ":2:13")),
                b.inputFiles());
        assertEquals(b.inputFiles(), b.copy().inputFiles(), "a copy keeps them");

        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nmesh { file \"m.obj\" }\n");
        assertEquals(2, SceneParser.parse(scene, roots).inputFiles().size());
        Path other = Files.createDirectories(dir.resolve("other"));
        SceneException refused = assertThrows(SceneException.class, () -> RenderJob.of(scene).assetRoots(AssetRoots.of(List.of(other))).run());
        assertEquals(scene + ": scene file is outside the allowed asset folders (" + dir.resolve("other").toRealPath() + ")", refused.getMessage());
    }

    @Test
    void aJobRefusesAnOutputThatIsAnInputBeforeItRenders() throws IOException, InterruptedException {
        Path tex = dir.resolve("t.pfm");
        Files.write(tex, new byte[] {'P', 'f', '\n', '1', ' ', '1', '\n', '-', '1', '\n', 0, 0, (byte) 0x80, 0x3f});
        Path scene = Files.writeString(dir.resolve("s.dat"), "camera { eye 0 0 -5 lookat 0 0 0 }\ntexture t { image \"t.pfm\" }\n"
                + "material m { map { texture t channel diffuse } }\nsphere { material m }\n");
        RenderJob job = RenderJob.of(scene).output(tex).settings(s -> s.toBuilder().size(4, 4).build());
        InputFile.OutputIsInputException e = assertThrows(InputFile.OutputIsInputException.class, job::run);
        assertEquals("output '" + tex + "' is an input of this run (the texture image named at " + scene + ":2:19); choose another name", e.getMessage());
        assertEquals(RenderJob.Stage.SETTINGS, job.stage(), "refused before the build and the render");
        assertEquals("texture image", e.input().what());
    }
}
