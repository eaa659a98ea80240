package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The speed line of --stats keeps three significant figures, so a slow (lazily refined) render does not print 0.0. */
class StatsFormatTest {
    @Test
    void keepsThreeSignificantFigures() {
        assertEquals("123.5", RenderCommand.threeFigures(123.456));
        assertEquals("12.3", RenderCommand.threeFigures(12.34));
        assertEquals("1.23", RenderCommand.threeFigures(1.234));
        assertEquals("0.0412", RenderCommand.threeFigures(0.04123));
        assertEquals("0.000500", RenderCommand.threeFigures(0.0005));
        assertEquals("0.0", RenderCommand.threeFigures(0));
    }
}
