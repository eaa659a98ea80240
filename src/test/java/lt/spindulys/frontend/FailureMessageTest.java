package lt.spindulys.frontend;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.concurrent.CancellationException;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.NonFinitePixelException;
import lt.spindulys.io.SceneException;

/** The one line for each kind of failure (cli.Main prints it; ViewerModelTest checks the viewer shows the same). */
class FailureMessageTest {
    @Test
    void eachFailureReadsAsTheCommandLinePrintsIt() {
        assertEquals("cube.obj:3:7: expected a number, found 'x'", FailureMessage.of(new SceneException("cube.obj", 3, 7, "expected a number, found 'x'")));
        assertEquals("Samples (samples) must be between 1 and 4, found 9", FailureMessage.of(new IllegalArgumentException("Samples (samples) must be between 1 and 4, found 9")));
        assertEquals("render: cannot write 'a.png': directory 'b' does not exist", FailureMessage.of(new IOException("cannot write 'a.png': directory 'b' does not exist")));
        assertEquals("cancelled; nothing written", FailureMessage.of(new CancellationException()));
        assertEquals("render: interrupted; nothing written", FailureMessage.of(new InterruptedException()));
        assertEquals("render: out of memory (give the JVM more with -Xmx, or lower the resolution)", FailureMessage.of(new OutOfMemoryError()));
        assertEquals("render: internal error: java.lang.NullPointerException", FailureMessage.of(new NullPointerException()));
        assertEquals("render: internal error: java.lang.IllegalArgumentException", FailureMessage.of(new IllegalArgumentException()));
        assertEquals("render: internal error: " + new NonFinitePixelException(3, 4).getMessage(), FailureMessage.of(new NonFinitePixelException(3, 4)));
    }

    @Test
    void aMessageStaysOneLine() {
        assertEquals("bad name 'a\\nb'", FailureMessage.of(new IllegalArgumentException("bad name 'a\nb'")));
    }
}
