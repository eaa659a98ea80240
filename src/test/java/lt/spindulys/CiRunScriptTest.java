package lt.spindulys;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The logic of {@code .ci/run} on a stage of stub commands: it installs the virtual X server when
 * it is missing (as root, through sudo, fetching package lists only when needed), runs the suite
 * under it, fails exactly when a test fails whatever xvfb-run itself exits with, and runs the suite
 * anyway (on an existing display or none) when the server cannot be had. The stubs log what they
 * were asked; PATH holds nothing else, so no real package manager or X server is touched.
 */
class CiRunScriptTest {
    @TempDir
    Path stage;

    private Path bin, log;

    private static final String XVFB_RUN = """
            #!/bin/bash
            # Logs its options (the authority file as AUTH, after checking it exists), then runs the command.
            line="xvfb-run"
            while [ "${1#-}" != "$1" ]; do
                case "$1" in
                    -a) line="$line -a"; shift ;;
                    -f) [ -f "$2" ] || { echo "no authority file $2" >&2; exit 6; }; line="$line -f AUTH"; shift 2 ;;
                    -s) line="$line -s $2"; shift 2 ;;
                    *) echo "unexpected option $1" >&2; exit 6 ;;
                esac
            done
            echo "$line" >> "$LOG"
            [ "${FAKE_XVFB_START:-ok}" = fail ] && exit 1
            DISPLAY=:99 "$@"
            status=$?
            [ "${FAKE_XVFB_CLEANUP:-ok}" = fail ] && exit 5
            exit $status
            """;

    @BeforeEach
    void stage() throws IOException, InterruptedException {
        assumeTrue(Files.isExecutable(Path.of("/bin/bash")), "needs /bin/bash to run .ci/run");
        Path ci = Files.createDirectories(stage.resolve("repo/.ci"));
        Files.copy(Path.of(".ci/run"), ci.resolve("run"));
        script(ci.resolve("library-example"), "#!/bin/bash\necho library-example >> \"$LOG\"\n");
        script(ci.resolve("slurm"), "#!/bin/bash\necho slurm >> \"$LOG\"\n");
        bin = Files.createDirectories(stage.resolve("bin"));
        log = stage.resolve("log");
        for (String tool : List.of("bash", "cat", "dirname", "mktemp", "rm", "true")) {
            Path real = which(tool);
            Files.createSymbolicLink(bin.resolve(tool), real);
        }
        script(bin.resolve("id"), "#!/bin/bash\necho \"${FAKE_UID:-0}\"\n");
        script(bin.resolve("mvn"), "#!/bin/bash\necho \"mvn $* DISPLAY=${DISPLAY:-}\" >> \"$LOG\"\nexit ${FAKE_MVN_EXIT:-0}\n");
        script(stage.resolve("xvfb-run.template"), XVFB_RUN);
    }

    private static Path which(String tool) {
        for (String dir : List.of("/usr/bin", "/bin")) {
            Path p = Path.of(dir, tool);
            if (Files.isExecutable(p)) return p;
        }
        assumeTrue(false, "needs " + tool + " in /usr/bin or /bin");
        return null;
    }

    private static void script(Path p, String text) throws IOException {
        Files.writeString(p, text, StandardCharsets.UTF_8);
        p.toFile().setExecutable(true);
    }

    private void withXvfb() throws IOException {
        Files.copy(stage.resolve("xvfb-run.template"), bin.resolve("xvfb-run"));
        bin.resolve("xvfb-run").toFile().setExecutable(true);
    }

    /** apt-get that fails to install until its lists are updated (when asked to), then installs the xvfb-run stub. */
    private void withAptGet() throws IOException {
        script(bin.resolve("apt-get"), """
                #!/bin/bash
                echo "apt-get $*" >> "$LOG"
                if [ "$1" = update ]; then echo updated > "$STAGE/lists"; exit 0; fi
                if [ "${FAKE_APT:-ok}" = needs-update ] && [ ! -e "$STAGE/lists" ]; then exit 100; fi
                [ "${FAKE_APT:-ok}" = broken ] && exit 100
                /bin/cp "$STAGE/xvfb-run.template" "$STAGE/bin/xvfb-run"
                /bin/chmod +x "$STAGE/bin/xvfb-run"
                """);
    }

    private void withSudo(boolean allowed) throws IOException {
        script(bin.resolve("sudo"), "#!/bin/bash\necho \"sudo $*\" >> \"$LOG\"\n[ \"$1\" = -n ] && shift\n"
                + (allowed ? "exec \"$@\"\n" : "echo 'sudo: a password is required' >&2\nexit 1\n"));
    }

    private record Run(int status, List<String> log, String stderr) {}

    private Run run(Map<String, String> env) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder("/bin/bash", stage.resolve("repo/.ci/run").toString());
        pb.environment().clear();
        pb.environment().put("PATH", bin.toString());
        pb.environment().put("LOG", log.toString());
        pb.environment().put("STAGE", stage.toString());
        pb.environment().put("TMPDIR", stage.toString());
        pb.environment().putAll(env);
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        Path err = stage.resolve("stderr");
        pb.redirectError(err.toFile());
        Process p = pb.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), ".ci/run finished");
        List<String> lines = Files.exists(log) ? Files.readAllLines(log) : List.of();
        return new Run(p.exitValue(), lines, Files.readString(err));
    }

    @Test
    void runsTheSuiteUnderTheVirtualServerThenTheLibraryExampleAndTheSchedulerProof() throws Exception {
        withXvfb();
        Run r = run(Map.of());
        assertEquals(0, r.status, r.stderr);
        assertEquals(List.of("xvfb-run -a -f AUTH -s -screen 0 1600x1000x24", "mvn -B test DISPLAY=:99", "library-example", "slurm"), r.log);
        try (java.util.stream.Stream<Path> left = Files.list(stage)) {
            assertEquals(List.of(), left.map(p -> p.getFileName().toString()).filter(n -> n.startsWith("tmp.")).toList(),
                    "the status and authority files are removed");
        }
    }

    @Test
    void aFailingTestFailsTheRunEvenWhenXvfbRunFailsToCleanUp() throws Exception {
        withXvfb();
        Run failed = run(Map.of("FAKE_MVN_EXIT", "1"));
        assertEquals(1, failed.status);
        assertEquals(List.of("xvfb-run -a -f AUTH -s -screen 0 1600x1000x24", "mvn -B test DISPLAY=:99"), failed.log, "no library example after a failure");
        Files.delete(log);
        Run both = run(Map.of("FAKE_MVN_EXIT", "1", "FAKE_XVFB_CLEANUP", "fail"));
        assertEquals(1, both.status, "the tests' status, not xvfb-run's");
        Files.delete(log);
        Run passed = run(Map.of("FAKE_XVFB_CLEANUP", "fail"));
        assertEquals(0, passed.status, "a passing suite is not failed by xvfb-run's cleanup: " + passed.stderr);
        assertTrue(passed.stderr.contains("the tests passed; xvfb-run then exited with 5 (ignored)"), passed.stderr);
    }

    @Test
    void anExistingDisplayIsReplacedByTheVirtualOne() throws Exception {
        withXvfb();
        Run r = run(Map.of("DISPLAY", ":0"));
        assertEquals(0, r.status, r.stderr);
        assertEquals("mvn -B test DISPLAY=:99", r.log.get(1));
    }

    @Test
    void asRootItInstallsXvfbFetchingThePackageListsOnlyWhenNeeded() throws Exception {
        withAptGet();
        Run r = run(Map.of("FAKE_APT", "needs-update"));
        assertEquals(0, r.status, r.stderr);
        assertEquals(List.of(
                "apt-get install -y -q --no-install-recommends xvfb xauth",
                "apt-get update -q",
                "apt-get install -y -q --no-install-recommends xvfb xauth",
                "xvfb-run -a -f AUTH -s -screen 0 1600x1000x24", "mvn -B test DISPLAY=:99", "library-example", "slurm"), r.log);
        Files.delete(log);
        Run again = run(Map.of());
        assertEquals(List.of("xvfb-run -a -f AUTH -s -screen 0 1600x1000x24", "mvn -B test DISPLAY=:99", "library-example", "slurm"), again.log,
                "installed once, used from then on");
    }

    @Test
    void notRootItInstallsThroughPasswordlessSudo() throws Exception {
        withAptGet();
        withSudo(true);
        Run r = run(Map.of("FAKE_UID", "1000"));
        assertEquals(0, r.status, r.stderr);
        assertTrue(r.log.contains("sudo -n apt-get install -y -q --no-install-recommends xvfb xauth"), r.log.toString());
        assertTrue(r.log.contains("mvn -B test DISPLAY=:99"), r.log.toString());
    }

    @Test
    void withoutAWayToInstallItTheSuiteRunsAnywayAndSaysWhy() throws Exception {
        withAptGet();
        withSudo(false);
        Run r = run(Map.of("FAKE_UID", "1000"));
        assertEquals(0, r.status, r.stderr);
        assertTrue(r.stderr.contains("installing it needs root (not root, no password-less sudo)"), r.stderr);
        assertTrue(r.stderr.contains("the real-window tests will say they were skipped"), r.stderr);
        assertTrue(r.log.contains("mvn -B test DISPLAY="), r.log.toString());
        assertTrue(r.log.stream().noneMatch(l -> l.startsWith("apt-get")), r.log.toString());
    }

    @Test
    void aFailedInstallOrServerFallsBackToTheExistingDisplay() throws Exception {
        withAptGet();
        Run broken = run(Map.of("FAKE_APT", "broken", "DISPLAY", ":5"));
        assertEquals(0, broken.status, broken.stderr);
        assertTrue(broken.stderr.contains("could not install xvfb"), broken.stderr);
        assertTrue(broken.stderr.contains("on the existing display DISPLAY=:5"), broken.stderr);
        assertEquals("mvn -B test DISPLAY=:5", broken.log.get(broken.log.size() - 3));

        Files.delete(log);
        withXvfb();
        Run noServer = run(Map.of("FAKE_XVFB_START", "fail", "FAKE_MVN_EXIT", "3"));
        assertEquals(3, noServer.status, "a failing suite still fails without the server");
        assertTrue(noServer.stderr.contains("the virtual X server did not start (xvfb-run exited with 1)"), noServer.stderr);
        assertEquals(List.of("xvfb-run -a -f AUTH -s -screen 0 1600x1000x24", "mvn -B test DISPLAY="), noServer.log);
    }

    @Test
    void withoutAptGetItSaysSo() throws Exception {
        Run r = run(Map.of());
        assertEquals(0, r.status, r.stderr);
        assertTrue(r.stderr.contains("xvfb-run is missing and there is no apt-get to install it"), r.stderr);
        assertEquals(List.of("mvn -B test DISPLAY=", "library-example", "slurm"), r.log);
    }
}
