package lt.spindulys.viewer;

import java.awt.AWTError;
import java.awt.AWTException;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.awt.Robot;
import java.util.Locale;

import org.junit.jupiter.api.extension.ConditionEvaluationResult;
import org.junit.jupiter.api.extension.ExecutionCondition;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Enables {@link DisplayTest}s only where windows can be opened and driven: not headless, DISPLAY
 * set (on X11 systems), the screen reachable and a {@link Robot} allowed. Decided once per JVM.
 */
public final class DisplayCondition implements ExecutionCondition {
    /** Decided on first use; a display does not come or go during a test run. */
    private static final class Verdict {
        static final String MISSING = missingDisplay();
        static {
            if (MISSING != null) System.err.println("display tests skipped: " + MISSING);
        }
    }

    @Override
    public ConditionEvaluationResult evaluateExecutionCondition(ExtensionContext context) {
        String missing = Verdict.MISSING;
        return missing == null ? ConditionEvaluationResult.enabled("a display is available")
                : ConditionEvaluationResult.disabled(missing);
    }

    /** @return null if windows can be opened here, else why not, starting "no display: " */
    static String missingDisplay() {
        String display = System.getenv("DISPLAY");
        String os = System.getProperty("os.name", "").toLowerCase(Locale.ROOT);
        boolean x11 = !os.contains("win") && !os.contains("mac");
        if (Boolean.getBoolean("java.awt.headless")) return "no display: java.awt.headless is true";
        if (x11 && (display == null || display.isBlank())) return "no display: DISPLAY is not set";
        try {
            if (GraphicsEnvironment.isHeadless()) return "no display: the JVM is headless";
            GraphicsEnvironment.getLocalGraphicsEnvironment().getDefaultScreenDevice();
            new Robot();
            return null;
        } catch (AWTError | AWTException | HeadlessException | UnsatisfiedLinkError | SecurityException e) {
            return "no display: cannot use DISPLAY=" + display + " (" + e.getMessage() + ")";
        }
    }
}
