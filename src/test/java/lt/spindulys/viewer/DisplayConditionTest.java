package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/**
 * The reason a display test gives for skipping, decided in child JVMs whose environment the test
 * sets (a JVM decides about its display once): so the skip is never silent and never wrong, with
 * or without a display where the suite runs.
 */
class DisplayConditionTest {
    /** The child: prints the verdict. */
    public static void main(String[] args) {
        String missing = DisplayCondition.missingDisplay();
        System.out.println(missing == null ? "display available" : missing);
    }

    private static String verdict(Map<String, String> env, String... jvmOptions) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(List.of(jvmOptions));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), DisplayConditionTest.class.getName()));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.DISCARD);
        pb.environment().remove("DISPLAY");
        pb.environment().putAll(env);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    private static void assumeX11() {
        String os = System.getProperty("os.name", "").toLowerCase(Locale.ROOT);
        assumeTrue(!os.contains("win") && !os.contains("mac"), "the DISPLAY variable matters on X11 systems only");
    }

    @Test
    void withoutDisplayTheReasonIsThatItIsNotSet() throws Exception {
        assumeX11();
        assertEquals("no display: DISPLAY is not set", verdict(Map.of()));
    }

    @Test
    void anUnreachableDisplayIsNamed() throws Exception {
        assumeX11();
        String v = verdict(Map.of("DISPLAY", ":4242"));
        assertTrue(v.startsWith("no display: cannot use DISPLAY=:4242 ("), v);
    }

    @Test
    void aHeadlessJvmSaysSo() throws Exception {
        assertEquals("no display: java.awt.headless is true", verdict(Map.of("DISPLAY", ":0"), "-Djava.awt.headless=true"));
    }

    @Test
    void theDisplayThisSuiteRunsOnIsUsedWhenThereIsOne() throws Exception {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isBlank(), "runs under a display only");
        assertEquals(DisplayCondition.missingDisplay() == null ? "display available" : DisplayCondition.missingDisplay(),
                verdict(Map.of("DISPLAY", display)), "a child JVM on the same display decides the same");
    }
}
