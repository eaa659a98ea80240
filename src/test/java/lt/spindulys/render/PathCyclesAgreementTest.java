package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Locale;
import java.util.zip.GZIPInputStream;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.io.SceneParser;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.IntegratorKind;
import lt.spindulys.scene.SceneBuilder;

/**
 * The path tracer against converged Blender Cycles 3.4 images of the same scenes (src/test/resources/cycles/,
 * see the README there for how they were made): the peer torus path traced (scenes/bench/path-torus.dat,
 * 4 bounces) and the Cornell box (scenes/cornell-box.dat, 8 bounces).
 *
 * <p>The measure is the mean relative difference, the summed absolute difference over the summed reference,
 * over every block of B x B pixels and channel: a ratio of sums, so that dark pixels (the black sky, the box's
 * shadowed corners) neither blow it up nor drop out. Our render is small and at a modest sample count, so it
 * is compared at block resolution, where its noise averages down: a block of B x B pixels at n samples each
 * has the noise of one pixel at B x B x n samples. The noise is measured, not assumed: the render is two
 * halves of different seeds, and half their mean relative difference from each other is what noise alone
 * adds to the difference from the reference (two independent halves differ by twice what their mean differs
 * from the truth, for Gaussian noise). That figure is in the message, and must be well under the 2 % bound
 * for the test to mean anything. Pixels that see the Cornell box's light are left out on both sides: a
 * Cycles area light does not show to camera rays, ours does.
 *
 * <p>A wrong light transport must fail: the Cornell box with one bounce instead of 8 is checked to differ
 * by more than the bound.
 */
class PathCyclesAgreementTest {
    /** The agreement asked for: at most 2 % mean relative difference. */
    static final double BOUND = 0.02;
    /** Our noise must stay well below the bound, or a pass or a failure says little. */
    static final double NOISE_BOUND = 0.01;

    @Test
    void torusWithFourBouncesAgreesWithCycles() throws Exception {
        Agreement a = compare(Path.of("scenes/bench/path-torus.dat"), "cycles/path-torus-cycles.pfm.gz", 4, 80, 45, 128, 5);
        assertTrue(a.noise() < NOISE_BOUND, a.toString());
        assertTrue(a.difference() <= BOUND, a.toString());
    }

    @Test
    void cornellBoxWithEightBouncesAgreesWithCycles() throws Exception {
        Agreement a = compare(Path.of("scenes/cornell-box.dat"), "cycles/cornell-box-cycles.pfm.gz", 8, 64, 64, 256, 8);
        assertTrue(a.noise() < NOISE_BOUND, a.toString());
        assertTrue(a.difference() <= BOUND, a.toString());
    }

    @Test
    void cornellBoxWithOneBounceDoesNotAgree() throws Exception {
        Agreement a = compare(Path.of("scenes/cornell-box.dat"), "cycles/cornell-box-cycles.pfm.gz", 1, 64, 64, 16, 8);
        assertTrue(a.difference() > BOUND, a.toString());
    }

    /** The mean relative difference from the reference, and what our noise alone contributes to it. */
    record Agreement(String scene, int maxDepth, double difference, double noise) {
        @Override
        public String toString() {
            return String.format(Locale.ROOT, "%s, maxdepth %d: mean relative difference %.2f %% (bound %.0f %%), of which noise about %.2f %%",
                    scene, maxDepth, 100 * difference, 100 * BOUND, 100 * noise);
        }
    }

    /**
     * Renders {@code scene} path traced at {@code maxDepth}, w x h pixels (the reference's size divided by a
     * whole number) and twice spp/2 samples per pixel, and compares it with the reference in blocks of
     * {@code block} pixels.
     */
    static Agreement compare(Path scene, String reference, int maxDepth, int w, int h, int spp, int block)
            throws Exception {
        Image ref = readPfm(reference);
        int k = ref.width / w;
        if (k * w != ref.width || k * h != ref.height) throw new IllegalArgumentException("the reference is " + ref.width + "x" + ref.height);
        double[] truth = downsample(ref, k);
        double[] first = render(scene, maxDepth, w, h, spp / 2, 1), second = render(scene, maxDepth, w, h, spp / 2, 2);
        double[] ours = new double[first.length];
        for (int i = 0; i < ours.length; i++) ours[i] = (first[i] + second[i]) / 2;
        boolean[] mask = lightPixels(SceneParser.parse(scene), w, h);
        return new Agreement(scene.getFileName().toString(), maxDepth, difference(ours, truth, mask, w, h, block),
                difference(first, second, mask, w, h, block) / 2);
    }

    private static double[] render(Path file, int maxDepth, int w, int h, int spp, long seed) throws Exception {
        SceneBuilder b = SceneParser.parse(file);
        b.settings(b.settings().toBuilder().integrator(IntegratorKind.PATH).maxDepth(maxDepth).size(w, h).samplesPerPixel(spp).seed(seed)
                .clamp(0).build());
        return Renderer.render(b.build(), 2, ProgressListener.NONE).frame().data();
    }

    /**
     * Pixels whose box may see an area light directly (its projected corners' bounding box, one pixel wider),
     * left out of the comparison because Cycles shows no area light to the camera.
     */
    static boolean[] lightPixels(SceneBuilder scene, int w, int h) {
        boolean[] mask = new boolean[w * h];
        if (!(scene.camera() instanceof PinholeCamera cam)) return mask;
        Vec3 f = cam.lookAt().minus(cam.eye()).normalized();
        Vec3 right = f.cross(cam.up()).normalized(), up = right.cross(f);
        double t = Math.tan(Math.toRadians(cam.fovDegrees()) / 2), aspect = w / (double) h;
        for (AreaLight l : scene.areaLights()) {
            double x0 = Double.POSITIVE_INFINITY, x1 = Double.NEGATIVE_INFINITY, y0 = x0, y1 = x1;
            for (int su = -1; su <= 1; su += 2) {
                for (int sv = -1; sv <= 1; sv += 2) {
                    Vec3 d = l.center().plus(l.halfU().times(su)).plus(l.halfV().times(sv)).minus(cam.eye());
                    double z = d.dot(f), px = (d.dot(right) / (z * t * aspect) + 1) / 2 * w, py = (1 - d.dot(up) / (z * t)) / 2 * h;
                    x0 = Math.min(x0, px); x1 = Math.max(x1, px); y0 = Math.min(y0, py); y1 = Math.max(y1, py);
                }
            }
            for (int y = Math.max(0, (int) Math.floor(y0) - 1); y <= Math.min(h - 1, (int) Math.floor(y1) + 1); y++) {
                for (int x = Math.max(0, (int) Math.floor(x0) - 1); x <= Math.min(w - 1, (int) Math.floor(x1) + 1); x++) mask[y * w + x] = true;
            }
        }
        return mask;
    }

    /**
     * Sum over blocks and channels of |mean a - mean b| over the sum of mean b, each mean over a block's
     * pixels outside the mask (the same pixels on both sides).
     */
    static double difference(double[] a, double[] b, boolean[] mask, int w, int h, int block) {
        double diff = 0, sum = 0;
        for (int by = 0; by + block <= h; by += block) {
            for (int bx = 0; bx + block <= w; bx += block) {
                for (int c = 0; c < 3; c++) {
                    double sa = 0, sb = 0;
                    int n = 0;
                    for (int y = by; y < by + block; y++) {
                        for (int x = bx; x < bx + block; x++) {
                            int p = y * w + x;
                            if (mask[p]) continue;
                            sa += a[3 * p + c];
                            sb += b[3 * p + c];
                            n++;
                        }
                    }
                    if (n == 0) continue;
                    diff += Math.abs(sa - sb) / n;
                    sum += sb / n;
                }
            }
        }
        return diff / sum;
    }

    /** A PFM image as linear RGB, top row first. */
    record Image(int width, int height, double[] rgb) {}

    /** The mean of each k x k square: a 1-pixel box filter at the finer size averaged is the box filter at the coarser one. */
    static double[] downsample(Image im, int k) {
        int w = im.width / k, h = im.height / k;
        double[] out = new double[3 * w * h];
        for (int y = 0; y < im.height; y++) {
            for (int x = 0; x < im.width; x++) {
                for (int c = 0; c < 3; c++) out[3 * ((y / k) * w + x / k) + c] += im.rgb[3 * (y * im.width + x) + c] / (k * k);
            }
        }
        return out;
    }

    /** Reads a gzipped little- or big-endian colour PFM (bottom row first in the file) from the test resources. */
    static Image readPfm(String resource) throws IOException {
        try (InputStream raw = PathCyclesAgreementTest.class.getClassLoader().getResourceAsStream(resource)) {
            if (raw == null) throw new IOException("test resource " + resource + " is missing");
            DataInputStream in = new DataInputStream(new BufferedInputStream(new GZIPInputStream(raw)));
            if (!token(in).equals("PF")) throw new IOException(resource + ": not a colour PFM");
            int w = Integer.parseInt(token(in)), h = Integer.parseInt(token(in));
            double scale = Double.parseDouble(token(in));
            byte[] bytes = in.readNBytes(12 * w * h);
            if (bytes.length != 12 * w * h) throw new IOException(resource + ": truncated");
            ByteBuffer buf = ByteBuffer.wrap(bytes).order(scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
            double[] rgb = new double[3 * w * h];
            for (int row = h - 1; row >= 0; row--) {
                for (int i = 0; i < 3 * w; i++) rgb[3 * w * row + i] = buf.getFloat();
            }
            return new Image(w, h, rgb);
        }
    }

    private static String token(DataInputStream in) throws IOException {
        StringBuilder sb = new StringBuilder();
        int c = in.read();
        while (Character.isWhitespace(c)) c = in.read();
        while (c != -1 && !Character.isWhitespace(c)) {
            sb.append((char) c);
            c = in.read();
        }
        return new String(sb.toString().getBytes(StandardCharsets.US_ASCII), StandardCharsets.US_ASCII);
    }
}
