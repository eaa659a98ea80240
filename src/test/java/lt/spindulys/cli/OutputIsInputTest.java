package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * An output that is one of the run's inputs (the same file, by name or through a link) is refused
 * with one line and exit status 2 before anything is written, for every command and every kind of
 * input: the scene file and each file it names, a render pass, a frame, a tile, a mesh to subdivide.
 */
class OutputIsInputTest {
    @TempDir Path dir;

    /** An input of the fixture scene, what the message calls it, and the file and token where it is named (null: given directly). */
    record Input(String file, String what, String namedIn, String token) {
        @Override public String toString() { return file; }
    }

    static Stream<Input> inputs() {
        return Stream.of(
                new Input("scene.dat", "scene file", null, null),
                new Input("m.obj", "mesh file", "scene.dat", "\"m.obj\""),
                new Input("m.mtl", "material library", "m.obj", "m.mtl"),
                new Input("tex.png", "texture image", "m.mtl", "tex.png"),
                new Input("img.png", "texture image", "scene.dat", "\"img.png\""),
                new Input("sky.png", "environment image", "scene.dat", "\"sky.png\""),
                new Input("cube.dat", "subdivision mesh file", "scene.dat", "\"cube.dat\""),
                new Input("cube.tex", "unwrap file", "scene.dat", "\"cube.tex\""));
    }

    private String expected(Path output, Input in, Path scene) throws IOException {
        if (in.namedIn() == null) return "render: output '" + output + "' is an input of this run (the " + in.what() + " '" + scene + "'); choose another name";
        Path namer = in.namedIn().equals("scene.dat") ? scene : dir.resolve(in.namedIn()).toAbsolutePath().normalize();
        return "render: output '" + output + "' is an input of this run (the " + in.what() + " named at " + namer + ":"
                + SceneFixture.at(Files.readString(namer), in.token()) + "); choose another name";
    }

    /** Exit status 2, the one line, the input unchanged and no file left beside it. */
    private void assertRefused(CliTest.Run r, String line, Path input, byte[] before) throws IOException {
        assertEquals(2, r.status(), r.err());
        assertEquals(line + System.lineSeparator(), r.err());
        assertArrayEquals(before, Files.readAllBytes(input), "the input is unchanged");
        try (Stream<Path> s = Files.list(input.toAbsolutePath().getParent())) {
            assertTrue(s.noneMatch(p -> p.getFileName().toString().endsWith(".tmp") || p.getFileName().toString().endsWith(".bak")), "nothing left");
        }
    }

    @ParameterizedTest(name = "{0}, through a hard link")
    @MethodSource("inputs")
    void anOutputLinkedToAnInputIsRefused(Input in) throws IOException {
        Path scene = SceneFixture.write(dir);
        Path input = dir.resolve(in.file());
        Path out = Files.createLink(dir.resolve("out.png"), input);
        byte[] before = Files.readAllBytes(input);
        assertRefused(CliTest.run(scene.toString(), "-o", out.toString(), "--width", "8", "--quiet"), expected(out, in, scene), input, before);
    }

    @ParameterizedTest(name = "{0}, through a symbolic link")
    @MethodSource("inputs")
    void anOutputThatIsALinkToAnInputIsRefused(Input in) throws IOException {
        Path scene = SceneFixture.write(dir);
        Path input = dir.resolve(in.file());
        Path out = Files.createSymbolicLink(dir.resolve("out.png"), input.getFileName());
        byte[] before = Files.readAllBytes(input);
        assertRefused(CliTest.run(scene.toString(), "-o", out.toString(), "--width", "8", "--quiet"), expected(out, in, scene), input, before);
        assertTrue(Files.isSymbolicLink(out), "the link is left as it was");
    }

    @ParameterizedTest
    @ValueSource(strings = {"tex.png", "img.png", "sky.png"})
    void anImageTheSceneReadsIsNotAnOutput(String image) throws IOException {
        Path scene = SceneFixture.write(dir);
        Input in = inputs().filter(i -> i.file().equals(image)).findFirst().orElseThrow();
        Path out = dir.resolve(image);
        assertRefused(CliTest.run(scene.toString(), "-o", out.toString(), "--width", "8", "--quiet"), expected(out, in, scene), out, SceneFixture.PNG);
    }

    @Test
    void theSceneFileIsNotAnOutputWhateverItsName() throws IOException {
        Path scene = dir.resolve("scene.png");
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nsphere { }\n");
        byte[] before = Files.readAllBytes(scene);
        assertRefused(CliTest.run(scene.toString(), "-o", scene.toString(), "--quiet"),
                "render: output '" + scene + "' is an input of this run (the scene file '" + scene + "'); choose another name", scene, before);
        Path relative = dir.resolve("sub/../scene.png");
        Files.createDirectories(dir.resolve("sub"));
        assertRefused(CliTest.run(scene.toString(), "-o", relative.toString(), "--quiet"),
                "render: output '" + relative + "' is an input of this run (the scene file '" + scene + "'); choose another name", scene, before);
    }

    @Test
    void aRenderPassBesideTheImageIsNotAnInput() throws IOException {
        Path scene = SceneFixture.write(dir);
        Path input = dir.resolve("tex.png");
        Path pass = Files.createLink(dir.resolve("out.normal.pfm"), input);
        Path out = dir.resolve("out.png");
        assertRefused(CliTest.run(scene.toString(), "-o", out.toString(), "--aov", "depth,normal", "--width", "8", "--quiet"),
                "render: output '" + pass + "' is an input of this run (the texture image named at " + dir.resolve("m.mtl").toAbsolutePath().normalize()
                        + ":3:8); choose another name", input, SceneFixture.PNG);
        assertFalse(Files.exists(out), "no image written");
        assertFalse(Files.exists(dir.resolve("out.depth.pfm")), "no pass written");
    }

    @Test
    void everyFrameIsCheckedBeforeTheFirstIsRendered() throws IOException {
        Files.write(dir.resolve("shot_0003.png"), SceneFixture.PNG);
        Path scene = dir.resolve("anim.dat");
        String text = "animation { frames 1 4 fps 24 }\ncamera { eye 0 0 -5 lookat 0 0 0 }\ntexture t { image \"shot_0003.png\" }\n"
                + "material m { map { texture t channel diffuse } }\nsphere { material m }\n";
        Files.writeString(scene, text);
        Path frame3 = dir.resolve("shot_0003.png");
        assertRefused(CliTest.run(scene.toString(), "-o", dir.resolve("shot_####.png").toString(), "--width", "8", "--quiet"),
                "render: output '" + frame3 + "' is an input of this run (the texture image named at " + scene + ":" + SceneFixture.at(text, "\"shot_0003")
                        + "); choose another name", frame3, SceneFixture.PNG);
        assertFalse(Files.exists(dir.resolve("shot_0001.png")), "not even the frames before it are rendered");
        // --skip-existing leaves the frame alone, so nothing is replaced: the others are rendered.
        CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve("shot_####.png").toString(), "--width", "8", "--quiet", "--skip-existing");
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(SceneFixture.PNG, Files.readAllBytes(frame3));
        assertTrue(Files.exists(dir.resolve("shot_0004.png")));
    }

    @Test
    void assembleRefusesToWriteOverOneOfItsTiles() throws IOException {
        Path scene = dir.resolve("s.dat");
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nsphere { }\n");
        List<String> tiles = new ArrayList<>();
        for (int i = 1; i <= 2; i++) {
            Path t = dir.resolve("t" + i + ".png");
            assertEquals(0, CliTest.run(scene.toString(), "--tile", i + "/2", "--width", "8", "-o", t.toString(), "--quiet").status());
            tiles.add(t.toString());
        }
        Path t1 = dir.resolve("t1.png"), t2 = dir.resolve("t2.png");
        byte[] before = Files.readAllBytes(t1);
        assertRefused(CliTest.run("assemble", t1.toString(), t2.toString(), "-o", t1.toString()),
                "render: output '" + t1 + "' is an input of this run (the tile '" + t1 + "'); choose another name", t1, before);
        byte[] before2 = Files.readAllBytes(t2);
        assertRefused(CliTest.run("assemble", dir.resolve("t*.png").toString(), "-o", t2.toString()),
                "render: output '" + t2 + "' is an input of this run (the tile '" + t2 + "'); choose another name", t2, before2);
        Path link = Files.createSymbolicLink(dir.resolve("frame.png"), t1.getFileName());
        assertRefused(CliTest.run("assemble", t1.toString(), t2.toString(), "-o", link.toString()),
                "render: output '" + link + "' is an input of this run (the tile '" + t1 + "'); choose another name", t1, before);
    }

    @Test
    void subdivideRefusesToWriteOverItsMeshItsUnwrapOrWhatItsSceneReads() throws IOException {
        Path mesh = Files.copy(Path.of("scenes/models/crease-cube.obj"), dir.resolve("g.obj"));
        byte[] before = Files.readAllBytes(mesh);
        assertRefused(CliTest.run("subdivide", mesh.toString(), "--level", "1", "-o", mesh.toString()),
                "render: output '" + mesh + "' is an input of this run (the mesh '" + mesh + "'); choose another name", mesh, before);

        Path cube = Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Path tex = Files.copy(Path.of("scenes/models/cube.tex"), dir.resolve("cube.tex"));
        Path uvOut = Files.createLink(dir.resolve("uv.obj"), tex);
        byte[] texBefore = Files.readAllBytes(tex);
        assertRefused(CliTest.run("subdivide", cube.toString(), "--level", "1", "--uv", tex.toString(), "-o", uvOut.toString()),
                "render: output '" + uvOut + "' is an input of this run (the unwrap '" + tex + "'); choose another name", tex, texBefore);

        Path scene = dir.resolve("s.dat");
        String text = "camera { eye 0 0 -5 lookat 0 0 0 }\nmesh { file \"g.obj\" }\nsubdiv { file \"cube.dat\" method projected }\n";
        Files.writeString(scene, text);
        assertRefused(CliTest.run("subdivide", cube.toString(), "--scene", scene.toString(), "-o", mesh.toString()),
                "render: output '" + mesh + "' is an input of this run (the mesh file named at " + scene + ":" + SceneFixture.at(text, "\"g.obj")
                        + "); choose another name", mesh, before);
        Path sceneObj = Files.createLink(dir.resolve("scene.obj"), scene);
        byte[] sceneBefore = Files.readAllBytes(scene);
        assertRefused(CliTest.run("subdivide", cube.toString(), "--scene", scene.toString(), "-o", sceneObj.toString()),
                "render: output '" + sceneObj + "' is an input of this run (the scene file '" + scene + "'); choose another name", scene, sceneBefore);
    }
}
