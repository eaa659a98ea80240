package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.io.AssetRoots;

/**
 * --assets-root and SPINDULYS_ASSETS_ROOT: a scene reads only inside the folders given, links
 * resolved; every key that names a file is refused outside them with one line at the key, exit
 * status 2 and nothing written.
 */
class AssetRootsCliTest {
    @TempDir Path dir;
    Path job, outside, out;

    @BeforeEach
    void files() throws IOException {
        job = dir.resolve("job");
        SceneFixture.write(job);
        outside = Files.createDirectories(dir.resolve("outside"));
        SceneFixture.write(outside);
        out = dir.resolve("out.png");
    }

    static CliTest.Run run(Map<String, String> env, String... args) {
        ByteArrayOutputStream o = new ByteArrayOutputStream(), e = new ByteArrayOutputStream();
        int status = Main.run(args, new PrintStream(o, true, StandardCharsets.UTF_8), new PrintStream(e, true, StandardCharsets.UTF_8), env);
        return new CliTest.Run(status, o.toString(StandardCharsets.UTF_8), e.toString(StandardCharsets.UTF_8));
    }

    private CliTest.Run render(Path scene, String... more) {
        List<String> args = new ArrayList<>(List.of(scene.toString(), "-o", out.toString(), "--width", "8", "--quiet", "--assets-root", job.toString()));
        args.addAll(List.of(more));
        return run(Map.of(), args.toArray(new String[0]));
    }

    private void assertRefused(CliTest.Run r, String line) {
        assertEquals(2, r.status(), r.err());
        assertEquals(line + System.lineSeparator(), r.err());
        assertFalse(Files.exists(out), "nothing written");
    }

    private String roots() throws IOException { return "(" + job.toRealPath() + ")"; }

    @Test
    void aSceneWhoseFilesAreAllInsideRenders() {
        CliTest.Run r = render(job.resolve("scene.dat"));
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.exists(out));
    }

    /** A key of the fixture scene: the file whose text names a file, what it names, and how to replace that name. */
    record Key(String what, String file, String name) {
        @Override public String toString() { return what + " in " + file; }
    }

    static Stream<Key> keys() {
        return Stream.of(
                new Key("mesh file", "scene.dat", "m.obj"),
                new Key("subdivision mesh file", "scene.dat", "cube.dat"),
                new Key("unwrap file", "scene.dat", "cube.tex"),
                new Key("texture image", "scene.dat", "img.png"),
                new Key("environment image", "scene.dat", "sky.png"),
                new Key("material library", "m.obj", "m.mtl"),
                new Key("texture image", "m.mtl", "tex.png"));
    }

    /** Replaces the name under the key in its file by {@code name}; returns where it now stands, as messages give it. */
    private String rename(Key k, String name) throws IOException {
        Path f = job.resolve(k.file());
        String text = Files.readString(f);
        boolean quoted = k.file().equals("scene.dat");
        String was = quoted ? "\"" + k.name() + "\"" : k.name();
        String now = quoted ? "\"" + name + "\"" : name;
        text = text.replace(was, now);
        Files.writeString(f, text);
        Path shown = k.file().equals("scene.dat") ? job.resolve("scene.dat") : f.toAbsolutePath().normalize();
        return shown + ":" + SceneFixture.at(text, now);
    }

    @ParameterizedTest(name = "{0}: ../ out of the folder")
    @MethodSource("keys")
    void aRelativeNameOutOfTheFolderIsRefused(Key k) throws IOException {
        String name = "../outside/" + k.name();
        String at = rename(k, name);
        assertRefused(render(job.resolve("scene.dat")), at + ": " + k.what() + " '" + name + "' is outside the allowed asset folders " + roots());
    }

    @ParameterizedTest(name = "{0}: an absolute name")
    @MethodSource("keys")
    void anAbsoluteNameOutsideIsRefused(Key k) throws IOException {
        String name = outside.toRealPath().resolve(k.name()).toString();
        String at = rename(k, name);
        assertRefused(render(job.resolve("scene.dat")), at + ": " + k.what() + " '" + name + "' is outside the allowed asset folders " + roots());
    }

    @ParameterizedTest(name = "{0}: a link out of the folder")
    @MethodSource("keys")
    void aLinkInsideToAFileOutsideIsRefused(Key k) throws IOException {
        Path link = job.resolve("link-" + k.name());
        Files.createSymbolicLink(link, outside.resolve(k.name()).toAbsolutePath());
        String at = rename(k, link.getFileName().toString());
        assertRefused(render(job.resolve("scene.dat")), at + ": " + k.what() + " '" + link.getFileName() + "' is outside the allowed asset folders " + roots()
                + ": it resolves to " + outside.toRealPath().resolve(k.name()));
    }

    @ParameterizedTest(name = "{0}: through a link to a folder inside")
    @MethodSource("keys")
    void aLinkInsideToAFileInsideIsRead(Key k) throws IOException {
        // A link to the folder itself, inside: the files beside each file are found through it too.
        Files.createSymbolicLink(job.resolve("sub"), job.toAbsolutePath());
        rename(k, k.file().equals("scene.dat") ? "sub/" + k.name() : job.resolve("sub").resolve(k.name()).toString());
        CliTest.Run r = render(job.resolve("scene.dat"));
        assertEquals(0, r.status(), r.err());
    }

    @Test
    void aFileOutsideThatDoesNotExistIsRefusedTheSameWay() throws IOException {
        Key k = new Key("mesh file", "scene.dat", "m.obj");
        String at = rename(k, "/no/such/dir/x.obj");
        assertRefused(render(job.resolve("scene.dat")), at + ": mesh file '/no/such/dir/x.obj' is outside the allowed asset folders " + roots());
    }

    @Test
    void theSceneFileMustBeInsideToo() throws IOException {
        Path scene = outside.resolve("scene.dat");
        assertRefused(render(scene), scene + ": scene file is outside the allowed asset folders " + roots());
    }

    @Test
    void theEnvironmentVariableConfinesAndAnOptionCannotWidenIt() throws IOException {
        String name = "../outside/m.obj";
        String at = rename(new Key("mesh file", "scene.dat", "m.obj"), name);
        Map<String, String> env = Map.of(AssetRoots.ENVIRONMENT_VARIABLE, "/nowhere-else-but" + java.io.File.pathSeparator + job);
        String[] args = {job.resolve("scene.dat").toString(), "-o", out.toString(), "--width", "8", "--quiet"};
        assertRefused(run(Map.of(AssetRoots.ENVIRONMENT_VARIABLE, job.toString()), args),
                at + ": mesh file '" + name + "' is outside the allowed asset folders " + roots());
        String[] wider = {job.resolve("scene.dat").toString(), "-o", out.toString(), "--width", "8", "--quiet", "--assets-root", dir.toString()};
        assertRefused(run(Map.of(AssetRoots.ENVIRONMENT_VARIABLE, job.toString()), wider),
                at + ": mesh file '" + name + "' is outside the allowed asset folders " + roots());
        // Without the variable the option given alone allows the wider folder.
        assertEquals(0, run(Map.of(), wider).status());
        assertEquals(2, run(env, args).status(), "a folder that does not exist is refused");
        assertEquals("render: " + AssetRoots.ENVIRONMENT_VARIABLE + ": asset folder '/nowhere-else-but' does not exist" + System.lineSeparator(), run(env, args).err());
    }

    @Test
    void anEmptyVariableConfinesNothing() {
        CliTest.Run r = run(Map.of(AssetRoots.ENVIRONMENT_VARIABLE, ""), outside.resolve("scene.dat").toString(), "-o", out.toString(), "--width", "8", "--quiet");
        assertEquals(0, r.status(), r.err());
    }

    @Test
    void aFolderThatIsNotOneIsBadUsage() {
        CliTest.Run r = run(Map.of(), job.resolve("scene.dat").toString(), "-o", out.toString(), "--assets-root", job.resolve("m.obj").toString());
        assertRefused(r, "render: --assets-root: asset folder '" + job.resolve("m.obj") + "' is not a folder");
    }

    @Test
    void everyFrameOfAnAnimationIsReadUnderTheSameFolders() throws IOException {
        Path scene = job.resolve("anim.dat");
        Files.writeString(scene, "animation { frames 1 2 fps 24 }\ncamera { eye 0 0 -5 lookat 0 0 0 }\nmesh { file \"../outside/m.obj\" }\n");
        CliTest.Run r = run(Map.of(), scene.toString(), "-o", dir.resolve("f_####.png").toString(), "--width", "8", "--quiet", "--assets-root", job.toString());
        assertEquals(2, r.status(), r.err());
        assertEquals(scene + ":3:13: mesh file '../outside/m.obj' is outside the allowed asset folders " + roots() + System.lineSeparator(), r.err());
        assertFalse(Files.exists(dir.resolve("f_0001.png")));
    }

    @Test
    void subdivideWithASceneReadsOnlyInsideTheFolders() throws IOException {
        Path scene = job.resolve("s.dat");
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nsubdiv { file \"cube.dat\" method projected }\nmesh { file \"../outside/m.obj\" }\n");
        Path obj = dir.resolve("out.obj");
        CliTest.Run r = run(Map.of(), "subdivide", job.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", obj.toString(), "--assets-root", job.toString());
        assertEquals(2, r.status(), r.err());
        assertEquals(scene + ":3:13: mesh file '../outside/m.obj' is outside the allowed asset folders " + roots() + System.lineSeparator(), r.err());
        assertFalse(Files.exists(obj));
        r = run(Map.of(AssetRoots.ENVIRONMENT_VARIABLE, job.toString()), "subdivide", job.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", obj.toString());
        assertEquals(2, r.status(), r.err());
        assertFalse(Files.exists(obj));
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nsubdiv { file \"cube.dat\" method projected }\n");
        r = run(Map.of(), "subdivide", job.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", obj.toString(), "--assets-root", job.toString());
        assertEquals(0, r.status(), r.err());
        r = run(Map.of(), "subdivide", job.resolve("cube.dat").toString(), "--level", "1", "-o", obj.toString(), "--assets-root", job.toString());
        assertEquals("render: --assets-root goes with --scene: it confines what a scene reads" + System.lineSeparator(), r.err());
    }
}
