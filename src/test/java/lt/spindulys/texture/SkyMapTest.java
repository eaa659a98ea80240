package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;


/**
 * The synthetic sky of scenes/environment.dat, textures/sky.hdr, is made by {@link #sky} and written
 * by our own RGBE writer; this keeps the committed file reproducible (rewrite it with
 * {@code java -cp target/classes:target/test-classes lt.spindulys.render.SkyMapTest}).
 *
 * <p>The sky, in the lat-long convention of scene.Environment (+Y up, the image's centre towards
 * +Z): a blue gradient from a pale horizon to the zenith, a sun 40 degrees up towards +X+Z, a
 * checkered ground (16 cells around, 8 from the horizon down) so that refraction's distortion shows,
 * and coloured posts on the horizon at the four compass points: red towards +X, green towards -X,
 * yellow towards +Z, white towards -Z.
 */
class SkyMapTest {
    static final int W = 512, H = 256;
    static final Path FILE = Path.of("textures/sky.hdr");

    static float[] sky() {
        float[] f = new float[3 * W * H];
        double sunEl = Math.toRadians(40), sunAz = Math.toRadians(45);
        double sx = Math.cos(sunEl) * Math.sin(sunAz), sy = Math.sin(sunEl), sz = Math.cos(sunEl) * Math.cos(sunAz);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double u = (x + 0.5) / W, v = (y + 0.5) / H;
                double phi = 2 * Math.PI * u, theta = Math.PI * v;
                // u = atan2(dx, -dz) / 2pi, v = acos(dy) / pi
                double dx = Math.sin(theta) * Math.sin(phi), dy = Math.cos(theta), dz = -Math.sin(theta) * Math.cos(phi);
                double r, g, b;
                if (dy >= 0) {
                    double t = Math.sqrt(dy);
                    r = 0.95 * (1 - t) + 0.18 * t;
                    g = 0.97 * (1 - t) + 0.35 * t;
                    b = 1.00 * (1 - t) + 0.85 * t;
                    double angle = Math.acos(Math.min(1, dx * sx + dy * sy + dz * sz));
                    double glow = angle < Math.toRadians(2.5) ? 40 : 1.5 * Math.exp(-angle / 0.15);
                    r += glow;
                    g += glow * 0.9;
                    b += glow * 0.7;
                } else {
                    int cu = (int) Math.floor(u * 16), cv = (int) Math.floor((v - 0.5) * 16);
                    double c = ((cu + cv) & 1) == 0 ? 0.45 : 0.12;
                    r = c;
                    g = c * 0.85;
                    b = c * 0.6;
                }
                // Posts on the horizon, 6 degrees wide and 12 high, at the compass points.
                double el = Math.PI / 2 - theta;
                if (el > -Math.toRadians(2) && el < Math.toRadians(12)) {
                    double[][] posts = {{0.25, 1, 0.1, 0.1}, {0.75, 0.1, 0.8, 0.1}, {0.5, 1, 0.9, 0.1}, {0, 1, 1, 1}};
                    for (double[] p : posts) {
                        double du = Math.abs(u - p[0]);
                        du = Math.min(du, 1 - du);
                        if (du < 3.0 / 360) { r = p[1]; g = p[2]; b = p[3]; }
                    }
                }
                int q = 3 * (y * W + x);
                f[q] = (float) r;
                f[q + 1] = (float) g;
                f[q + 2] = (float) b;
            }
        }
        return f;
    }

    static byte[] encoded() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        HdrWriter.write(out, W, H, sky(), true);
        return out.toByteArray();
    }

    @Test
    void theCommittedSkyIsTheOneThisMakes() throws IOException {
        byte[] made = encoded();
        assertTrue(made.length < 200_000, made.length + " bytes");
        assertArrayEquals(made, Files.readAllBytes(FILE), FILE + " differs from what SkyMapTest.sky() makes");
    }

    public static void main(String[] args) throws IOException {
        Files.write(FILE, encoded());
        System.out.println("wrote " + FILE);
    }
}
