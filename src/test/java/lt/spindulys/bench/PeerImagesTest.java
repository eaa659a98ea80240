package lt.spindulys.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PeerImagesTest {
    private static Path ppm(Path dir, String header, int... bytes) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        b.writeBytes(header.getBytes(StandardCharsets.US_ASCII));
        for (int x : bytes) b.write(x);
        Path p = dir.resolve("x.ppm");
        Files.write(p, b.toByteArray());
        return p;
    }

    @Test
    void readsBinaryPpmWithComments(@TempDir Path dir) throws IOException {
        Path p = ppm(dir, "P6\n# made by a test\n2 1\n255\n", 255, 0, 0, 1, 2, 3);
        assertArrayEquals(new int[] {0xFF0000, 0x010203}, PeerImages.readPpm(p, 2, 1, false));
    }

    /** Embree writes linear values; they are sRGB-encoded as ours are. */
    @Test
    void linearPpmIsEncoded(@TempDir Path dir) throws IOException {
        Path p = ppm(dir, "P6 1 1 255\n", 0, 55, 255);
        // linear 55/255 = 0.216 -> sRGB 0.502 -> 128
        assertArrayEquals(new int[] {0x0080FF}, PeerImages.readPpm(p, 1, 1, true));
    }

    @Test
    void refusesAnotherSizeOrFormat(@TempDir Path dir) throws IOException {
        Path p = ppm(dir, "P6\n2 1\n255\n", 0, 0, 0, 0, 0, 0);
        IOException e = assertThrows(IOException.class, () -> PeerImages.readPpm(p, 1280, 720, false));
        assertTrue(e.getMessage().contains("found 2x1 with maxval 255, expected 1280x720"), e.getMessage());
        Path q = ppm(dir, "P3\n1 1\n255\n0 0 0\n");
        assertThrows(IOException.class, () -> PeerImages.readPpm(q, 1, 1, false));
        Path t = ppm(dir, "P6\n2 1\n255\n", 0, 0, 0);
        assertTrue(assertThrows(IOException.class, () -> PeerImages.readPpm(t, 2, 1, false)).getMessage().contains("truncated"));
    }

    @Test
    void comparesLuma() {
        int[] a = {0x000000, 0x808080, 0xFFFFFF, 0x102030};
        assertEquals(0, PeerImages.compare(a, a).meanLuma());
        assertEquals(0, PeerImages.compare(a, a).shareOff());
        int[] b = {0x000000, 0x808080, 0xFFFFFF, 0x102030 + 0x141414}; // one pixel 20 steps brighter
        PeerImages.Difference d = PeerImages.compare(a, b);
        assertEquals(20 / 4.0, d.meanLuma(), 1e-9);
        assertEquals(0.25, d.shareOff(), 1e-12);
        int[] c = {0x0A0A0A, 0x808080, 0xFFFFFF, 0x102030}; // 10 steps: under 5 % of 255
        assertEquals(0, PeerImages.compare(a, c).shareOff());
    }
}
