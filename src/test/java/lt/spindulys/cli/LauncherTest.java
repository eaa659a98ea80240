package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code ./render} launcher run through symbolic links, as from {@code ~/bin/render}. It runs
 * in a copy of the repository's layout (the script, a jar of the compiled classes newer than
 * {@code src/main} and {@code pom.xml}), so it never starts a Maven build of its own.
 */
class LauncherTest {
    @TempDir Path dir;

    @Test
    void findsItsJarThroughAChainOfSymbolicLinks() throws Exception {
        Path bash = bash();
        Path script = repoWithLauncher();
        Path repo = script.getParent();
        assumeTrue(script.toFile().setExecutable(true), "cannot mark the copied launcher executable");
        FileTime past = FileTime.fromMillis(System.currentTimeMillis() - 3_600_000);
        Files.setLastModifiedTime(repo.resolve("src/main"), past);
        Files.setLastModifiedTime(repo.resolve("pom.xml"), past);
        writeJar(repo.resolve("target/render.jar"));

        // A relative link to an absolute one, each in another folder: ~/bin/render -> ../lib/render -> /repo/render.
        Path bin = Files.createDirectories(dir.resolve("home/bin")), lib = Files.createDirectories(dir.resolve("home/lib"));
        try {
            Files.createSymbolicLink(lib.resolve("render"), script.toAbsolutePath());
            Files.createSymbolicLink(bin.resolve("render"), Path.of("../lib/render"));
        } catch (UnsupportedOperationException | IOException e) {
            assumeTrue(false, "symbolic links cannot be made here: " + e);
        }

        // Run from an unrelated folder, with this JVM's java first on the PATH.
        ProcessBuilder pb = new ProcessBuilder(List.of(bash.toString(), bin.resolve("render").toString(), "--version"))
                .directory(dir.toFile()).redirectErrorStream(true);
        String javaBin = Path.of(System.getProperty("java.home"), "bin").toString();
        pb.environment().merge("PATH", javaBin, (old, add) -> add + java.io.File.pathSeparator + old);
        pb.environment().remove("SPINDULYS_JAVA_OPTS");
        Process p = pb.start();
        p.getOutputStream().close();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher did not finish");
        assertEquals(0, p.exitValue(), output);
        assertTrue(output.startsWith("spindulys "), output);
        assertFalse(output.contains("building"), "the launcher must use the jar beside the real script: " + output);
    }

    /**
     * A stale jar is rebuilt by Maven, whose quiet batch mode still prints bare colour resets
     * (ESC[0m): what reaches the user or a farm's log is plain text, and a failed build is said
     * in one line with exit status 1.
     */
    @Test
    void buildsTheJarWithoutColourCodesAndReportsAFailedBuild() throws Exception {
        Path bash = bash();
        Path script = repoWithLauncher();
        Path repo = script.getParent();
        Path built = dir.resolve("built.jar");
        writeJar(built);
        // A stand-in for Maven: prints what Maven 3.8 prints, then "builds" the jar by copying one,
        // or fails when told to.
        Path fakeBin = Files.createDirectories(dir.resolve("fake-bin"));
        Path mvn = fakeBin.resolve("mvn");
        Files.writeString(mvn, "#!/usr/bin/env bash\n"
                + "printf '\\033[0m\\033[0m'\n"
                + "if [ -n \"${FAIL_BUILD:-}\" ]; then printf '\\033[1;31m[ERROR]\\033[m compilation failed\\n' >&2; exit 1; fi\n"
                + "mkdir -p target && cp '" + built + "' target/render.jar\n"
                + "printf '\\033[0m\\033[0m' >&2\n");
        assumeTrue(mvn.toFile().setExecutable(true), "cannot mark the stand-in for Maven executable");
        String javaBin = Path.of(System.getProperty("java.home"), "bin").toString();

        ProcessBuilder failing = new ProcessBuilder(List.of(bash.toString(), script.toString(), "--version")).directory(dir.toFile()).redirectErrorStream(true);
        failing.environment().put("PATH", fakeBin + java.io.File.pathSeparator + javaBin + java.io.File.pathSeparator + failing.environment().get("PATH"));
        failing.environment().put("FAIL_BUILD", "1");
        String[] out = new String[1];
        int status = run(failing, out);
        assertEquals(1, status, out[0]);
        assertFalse(out[0].contains("\u001b"), "colour codes reached the output: " + out[0]);
        assertTrue(out[0].contains("[ERROR] compilation failed") && out[0].contains("render: the Maven build failed"), out[0]);
        assertFalse(Files.exists(repo.resolve("target/render.jar")));

        ProcessBuilder building = new ProcessBuilder(List.of(bash.toString(), script.toString(), "--version")).directory(dir.toFile()).redirectErrorStream(true);
        building.environment().put("PATH", fakeBin + java.io.File.pathSeparator + javaBin + java.io.File.pathSeparator + building.environment().get("PATH"));
        building.environment().remove("SPINDULYS_JAVA_OPTS");
        status = run(building, out);
        assertEquals(0, status, out[0]);
        assertFalse(out[0].contains("\u001b"), "colour codes reached the output: " + out[0]);
        assertEquals("render: building target/render.jar with Maven...\nspindulys ", out[0].substring(0, Math.min(out[0].length(), 59)));
    }

    /** The bash that runs the launcher; the test is skipped without one. */
    private static Path bash() {
        Path bash = Stream.of("/bin/bash", "/usr/bin/bash", "/usr/local/bin/bash").map(Path::of).filter(Files::isExecutable).findFirst().orElse(null);
        assumeTrue(bash != null, "no bash on this system: the launcher is a bash script");
        return bash;
    }

    /** A copy of the repository's layout around the launcher (the script, src/main, pom.xml); returns the script. */
    private Path repoWithLauncher() throws IOException {
        Path repo = Files.createDirectories(dir.resolve("repo"));
        Path script = repo.resolve("render");
        Files.copy(Path.of("render"), script);
        Files.createDirectories(repo.resolve("src/main"));
        Files.writeString(repo.resolve("pom.xml"), "<project/>\n");
        return script;
    }

    private static int run(ProcessBuilder pb, String[] output) throws Exception {
        Process p = pb.start();
        p.getOutputStream().close();
        output[0] = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher did not finish");
        return p.exitValue();
    }

    /** A runnable jar of the classes under test. */
    private static void writeJar(Path jar) throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        assumeTrue(Files.isDirectory(classes), "the classes under test are not in a folder: " + classes);
        Files.createDirectories(jar.getParent());
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        m.getMainAttributes().put(Attributes.Name.MAIN_CLASS, Main.class.getName());
        try (JarOutputStream out = new JarOutputStream(Files.newOutputStream(jar), m); Stream<Path> files = Files.walk(classes)) {
            for (Path f : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator) {
                out.putNextEntry(new JarEntry(classes.relativize(f).toString().replace(java.io.File.separatorChar, '/')));
                Files.copy(f, (OutputStream) out);
                out.closeEntry();
            }
        }
    }
}
