package lt.spindulys;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
 * What {@code .ci/slurm} does when Slurm cannot be had, on a stage of stub commands (PATH holds
 * nothing else, so no package manager or daemon is touched): it says so on a line starting
 * {@code .ci/slurm: SKIPPED} and exits 0, unless SPINDULYS_SLURM=require makes that a failure;
 * and it tries to install Debian's packages only as root or through password-less sudo. The proof
 * itself, on a real one-node cluster, is what {@code .ci/run} runs.
 */
class CiSlurmScriptTest {
    @TempDir
    Path stage;

    private Path bin, log;

    @BeforeEach
    void stage() throws IOException {
        assumeTrue(Files.isExecutable(Path.of("/bin/bash")), "needs /bin/bash to run .ci/slurm");
        Path ci = Files.createDirectories(stage.resolve("repo/.ci"));
        Files.copy(Path.of(".ci/slurm"), ci.resolve("slurm"));
        bin = Files.createDirectories(stage.resolve("bin"));
        log = stage.resolve("log");
        for (String tool : List.of("bash", "dirname")) {
            Path real = Files.isExecutable(Path.of("/usr/bin", tool)) ? Path.of("/usr/bin", tool) : Path.of("/bin", tool);
            assumeTrue(Files.isExecutable(real), "needs " + tool);
            Files.createSymbolicLink(bin.resolve(tool), real);
        }
        script(bin.resolve("id"), "#!/bin/bash\necho \"${FAKE_UID:-0}\"\n");
    }

    private static void script(Path p, String text) throws IOException {
        Files.writeString(p, text, StandardCharsets.UTF_8);
        p.toFile().setExecutable(true);
    }

    private record Run(int status, List<String> log, String stderr) {}

    private Run run(Map<String, String> env) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder("/bin/bash", stage.resolve("repo/.ci/slurm").toString());
        pb.environment().clear();
        pb.environment().put("PATH", bin.toString());
        pb.environment().put("LOG", log.toString());
        pb.environment().putAll(env);
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        Path err = stage.resolve("stderr");
        pb.redirectError(err.toFile());
        Process p = pb.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), ".ci/slurm finished");
        List<String> lines = Files.exists(log) ? Files.readAllLines(log) : List.of();
        return new Run(p.exitValue(), lines, Files.readString(err));
    }

    @Test
    void withoutAptGetItSaysItSkippedAndPassesUnlessRequired() throws Exception {
        Run r = run(Map.of());
        assertEquals(0, r.status, r.stderr);
        assertTrue(r.stderr.startsWith(".ci/slurm: SKIPPED the real-scheduler proof: Slurm is not installed and there is no apt-get to install it\n"), r.stderr);
        Run required = run(Map.of("SPINDULYS_SLURM", "require"));
        assertEquals(1, required.status, required.stderr);
        assertTrue(required.stderr.startsWith(".ci/slurm: FAILED: Slurm is not installed and there is no apt-get to install it (SPINDULYS_SLURM=require)"),
                required.stderr);
        Run bad = run(Map.of("SPINDULYS_SLURM", "maybe"));
        assertEquals(1, bad.status, bad.stderr);
    }

    @Test
    void itInstallsOnlyAsRootOrThroughSudoAndFetchesListsOnlyWhenNeeded() throws Exception {
        script(bin.resolve("apt-get"), "#!/bin/bash\necho \"apt-get $*\" >> \"$LOG\"\n[ \"$1\" = update ] && exit 0\nexit 100\n");
        Run notRoot = run(Map.of("FAKE_UID", "1000"));
        assertEquals(0, notRoot.status, notRoot.stderr);
        assertTrue(notRoot.stderr.contains("SKIPPED the real-scheduler proof: Slurm is not installed and installing it needs root"), notRoot.stderr);
        assertEquals(List.of(), notRoot.log);

        Run root = run(Map.of());
        assertEquals(0, root.status, root.stderr);
        assertEquals(List.of("apt-get install -y -q --no-install-recommends slurmctld slurmd slurm-client munge", "apt-get update -q",
                "apt-get install -y -q --no-install-recommends slurmctld slurmd slurm-client munge"), root.log);
        assertTrue(root.stderr.contains("SKIPPED the real-scheduler proof: apt-get could not install slurmctld slurmd slurm-client munge"), root.stderr);
    }

    @Test
    void skipSkipsWithoutTrying() throws Exception {
        script(bin.resolve("apt-get"), "#!/bin/bash\necho \"apt-get $*\" >> \"$LOG\"\nexit 100\n");
        Run r = run(Map.of("SPINDULYS_SLURM", "skip"));
        assertEquals(0, r.status, r.stderr);
        assertEquals(".ci/slurm: SKIPPED the real-scheduler proof: SPINDULYS_SLURM=skip\n", r.stderr);
        assertFalse(Files.exists(log));
    }
}
