package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.util.concurrent.CancellationException;

import org.junit.jupiter.api.Test;

import lt.spindulys.io.SceneException;

class UserMessagesTest {
    @Test
    void eachFailureReadsAsTheCommandLinePrintsIt() {
        assertEquals("cube.obj:3:7: expected a number, found 'x'", UserMessages.of(new SceneException("cube.obj", 3, 7, "expected a number, found 'x'")));
        assertEquals("Samples (samples) must be between 1 and 4, found 9", UserMessages.of(new IllegalArgumentException("Samples (samples) must be between 1 and 4, found 9")));
        assertEquals("render: cannot write 'a.png': directory 'b' does not exist", UserMessages.of(new IOException("cannot write 'a.png': directory 'b' does not exist")));
        assertEquals("cancelled; nothing written", UserMessages.of(new CancellationException()));
        assertEquals("render: interrupted; nothing written", UserMessages.of(new InterruptedException()));
        assertEquals("render: out of memory (give the JVM more with -Xmx, or lower the resolution)", UserMessages.of(new OutOfMemoryError()));
        assertEquals("render: internal error: java.lang.NullPointerException", UserMessages.of(new NullPointerException()));
        assertEquals("render: internal error: java.lang.IllegalArgumentException", UserMessages.of(new IllegalArgumentException()));
    }

    @Test
    void aMessageStaysOneLine() {
        assertEquals("bad name 'a\\nb'", UserMessages.of(new IllegalArgumentException("bad name 'a\nb'")));
    }
}
