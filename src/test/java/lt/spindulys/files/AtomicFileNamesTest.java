package lt.spindulys.files;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@link AtomicFile}'s temporary names: short whatever the target's, recognisable by {@link AtomicFile#isTemporaryName}. */
class AtomicFileNamesTest {
    @TempDir Path dir;

    /** A name of exactly {@code bytes} bytes ending in {@code ext}. */
    static String nameOf(int bytes, String ext) {
        return "n".repeat(bytes - ext.length()) + ext;
    }

    private List<String> listing() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aTargetNameOf255BytesIsProbedAndWritten() throws IOException {
        Path out = dir.resolve(nameOf(255, ".png"));
        AtomicFile.checkWritable(out);
        assertEquals(List.of(), listing(), "the probe leaves nothing");
        List<String> during = new ArrayList<>();
        AtomicFile.write(out, os -> {
            os.write("x".getBytes(StandardCharsets.UTF_8));
            during.addAll(listing());
        });
        assertEquals(1, during.size(), during.toString());
        assertTrue(AtomicFile.isTemporaryName(during.get(0)), during.get(0));
        assertTrue(during.get(0).length() < 40, during.get(0));
        assertEquals(List.of(out.getFileName().toString()), listing());
        assertEquals("x", Files.readString(out));
    }

    @Test
    void aGroupOfLongNamesIsWrittenToo() throws IOException {
        Path a = Files.writeString(dir.resolve(nameOf(255, ".a")), "old");
        Path b = dir.resolve(nameOf(254, ".b"));
        AtomicFile.writeAll(List.of(a, b), List.of(os -> os.write('1'), os -> os.write('2')));
        assertEquals("1", Files.readString(a));
        assertEquals("2", Files.readString(b));
        assertEquals(2, listing().size(), "no temporary or backup left: " + listing());
    }

    @Test
    void aNameTooLongForTheFileSystemIsRefusedBeforeAnythingIsWritten() throws IOException {
        Path out = dir.resolve(nameOf(256, ".png"));
        IOException e = assertThrows(IOException.class, () -> AtomicFile.checkWritable(out));
        assertTrue(e.getMessage().startsWith("cannot write '" + out + "': "), e.getMessage());
        assertTrue(e.getMessage().toLowerCase().contains("too long"), e.getMessage());
        assertEquals(List.of(), listing());
    }

    @Test
    void temporaryNamesAreRecognisedExactly() {
        assertTrue(AtomicFile.isTemporaryName(".spindulys-0123456789abcdef.tmp"));
        assertFalse(AtomicFile.isTemporaryName(".spindulys-0123456789abcdef.bak"));
        assertFalse(AtomicFile.isTemporaryName(".spindulys-0123456789ABCDEF.tmp"));
        assertFalse(AtomicFile.isTemporaryName(".spindulys-0123456789abcde.tmp"));
        assertFalse(AtomicFile.isTemporaryName("spindulys-0123456789abcdef.tmp"));
        assertFalse(AtomicFile.isTemporaryName(".out.png.0123456789abcdef.tmp"));
        assertFalse(AtomicFile.isTemporaryName("out.tmp"));
        assertFalse(AtomicFile.isTemporaryName(null));
        assertTrue(AtomicFile.TEMPORARY_PREFIX.startsWith("."));
        assertEquals(".tmp", AtomicFile.TEMPORARY_SUFFIX);
    }
}
