package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Seeded hostile input against the promise "bad input gives exit 2 and one located line, nothing
 * written": {@link InputFuzz} mutates every scene of scenes/, three scenes of its own dense in the
 * newer syntaxes (animation, keys, turntables, area lights, environments, adaptive subdivision,
 * OBJ materials, motion), and the files they name: meshes, unwraps, .mtl libraries (through
 * mtllib) and their maps, PNG, TGA, Radiance .hdr and .pfm images (token deletion, duplication and
 * swap; keywords swapped for their siblings; numbers, and the values of the newer keys, replaced by
 * NaN, infinities, denormals, huge and negative values and values at the limits; lines repeated up
 * to 1000 times; truncation; binary noise; control characters; huge words, counts and sizes; deep
 * CSG nesting; statements of the newer syntaxes added; image headers, sizes, run-length rows and
 * float values) and renders each case. It runs in a child JVM with a small heap, so that the memory checks are
 * what stops a case that asks for too much, not the test JVM's generous heap.
 */
class InputFuzzTest {
    /** Cases per run: a few hundred within about half a minute on two cores. */
    static final int CASES = 250;
    static final long SEED = 20261202L;
    /** The child's heap: small, as a user's default heap on a small machine. */
    static final String HEAP = "-Xmx192m";

    @TempDir Path work;

    @Test
    void hostileInputRendersOrFailsWithOneLocatedLine() throws IOException, InterruptedException {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        List<String> cmd = new ArrayList<>(List.of(java.toString(), HEAP));
        if (ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent()) cmd.addAll(List.of("--add-modules", "jdk.incubator.vector"));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), InputFuzz.class.getName(),
                Long.toString(SEED), Integer.toString(CASES), Path.of("").toAbsolutePath().toString(), work.resolve("fuzz").toString()));
        Path log = work.resolve("fuzz.log");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        if (!p.waitFor(4, TimeUnit.MINUTES)) {
            p.destroyForcibly();
            fail("the fuzz run did not finish in 4 minutes; its log so far:\n" + tail(log));
        }
        List<String> lines = Files.readAllLines(log, StandardCharsets.UTF_8);
        List<String> failures = lines.stream().filter(l -> l.startsWith("FAIL ")).toList();
        String summary = lines.stream().filter(l -> l.startsWith("SUMMARY ")).findFirst().orElse(null);
        assertNotNull(summary, "the fuzz run ended without its summary (exit " + p.exitValue() + "):\n" + tail(log));
        assertTrue(summary.contains("cases=" + CASES + " "), summary);
        assertTrue(failures.isEmpty(), failures.size() + " of " + CASES + " cases broke the promise (" + summary + "); rerun with "
                + "InputFuzz " + SEED + " " + CASES + " to reproduce:\n" + String.join("\n", failures));
        // The mutations must reach both outcomes, or the test proves little.
        assertFalse(summary.contains(" rendered=0 "), summary);
        assertFalse(summary.contains(" refused=0 "), summary);
    }

    private static String tail(Path log) throws IOException {
        if (!Files.exists(log)) return "(no log)";
        List<String> l = Files.readAllLines(log, StandardCharsets.UTF_8);
        return String.join("\n", l.subList(Math.max(0, l.size() - 40), l.size()));
    }
}
