package lt.spindulys.denoise;

import static org.junit.jupiter.api.Assertions.*;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.FrameBuffer;

/**
 * The denoiser on synthetic frames whose noise-free truth is known: a colour that is albedo
 * times a light level, plus Gaussian noise of a known variance, with the features a render
 * would gather for it.
 */
class DenoiserTest {
    private static final int W = 48, H = 40;
    private static final double SIGMA = 0.08;

    /** A synthetic frame: truth, noisy colour, features. */
    private record Synthetic(FrameBuffer truth, FrameBuffer noisy, FeatureFrame features) {}

    /**
     * A frame of albedo {@code albedo(x, y)} lit by {@code light(x, y)}, facing normal
     * {@code normal(x, y)} (0 = +z, 1 = +x), noise of standard deviation sigma added.
     */
    private static Synthetic synthetic(java.util.function.IntBinaryOperator albedoCode, double[] albedos,
                                       java.util.function.IntBinaryOperator face, double[] lights, double sigma, long seed) {
        FrameBuffer truth = new FrameBuffer(W, H), noisy = new FrameBuffer(W, H);
        FeatureFrame f = new FeatureFrame(W, H);
        SplittableRandom rng = new SplittableRandom(seed);
        double[] v = new double[FeatureFrame.VALUES];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double a = albedos[albedoCode.applyAsInt(x, y)];
                int n = face.applyAsInt(x, y);
                double t = a * lights[n];
                truth.set(x, y, t, t, t);
                noisy.set(x, y, t + sigma * rng.nextGaussian(), t + sigma * rng.nextGaussian(), t + sigma * rng.nextGaussian());
                v[0] = v[1] = v[2] = a;
                v[3] = n == 1 ? 1 : 0; v[4] = 0; v[5] = n == 0 ? 1 : 0;
                v[6] = 0.25;
                v[7] = v[8] = v[9] = sigma * sigma;
                f.put(x, y, v, false, 1);
            }
        }
        return new Synthetic(truth, noisy, f);
    }

    private static double meanSquaredError(FrameBuffer a, FrameBuffer truth) {
        double sum = 0;
        for (int i = 0; i < a.data().length; i++) sum += (a.data()[i] - truth.data()[i]) * (a.data()[i] - truth.data()[i]);
        return sum / a.data().length;
    }

    @Test
    void aFlatNoiseFreeFrameIsUnchanged() throws InterruptedException {
        Synthetic s = synthetic((x, y) -> 0, new double[] {0.6}, (x, y) -> 0, new double[] {0.7}, 0, 1);
        FrameBuffer out = new Denoiser().denoise(s.noisy(), s.features(), 2);
        for (int i = 0; i < out.data().length; i++) assertEquals(0.42, out.data()[i], 1e-9);
    }

    @Test
    void aNoiseFreeCheckerIsUnchanged() throws InterruptedException {
        // No noise: only identical patches weigh, so the texture comes back as it was.
        Synthetic s = synthetic((x, y) -> ((x / 4) + (y / 4)) % 2, new double[] {0.1, 0.9}, (x, y) -> 0, new double[] {1}, 0, 1);
        FrameBuffer out = new Denoiser().denoise(s.noisy(), s.features(), 2);
        assertTrue(meanSquaredError(out, s.truth()) < 1e-12, "error " + meanSquaredError(out, s.truth()));
    }

    @Test
    void aNoisyCheckerKeepsItsContrastAndLosesItsNoise() throws InterruptedException {
        // Squares of 3 pixels: every pixel is at most one pixel from an albedo edge.
        Synthetic s = synthetic((x, y) -> ((x / 3) + (y / 3)) % 2, new double[] {0.15, 0.85}, (x, y) -> 0, new double[] {0.8}, SIGMA, 2);
        FrameBuffer out = new Denoiser().denoise(s.noisy(), s.features(), 2);
        double noisy = meanSquaredError(s.noisy(), s.truth()), denoised = meanSquaredError(out, s.truth());
        assertTrue(denoised < noisy / 10, "noisy " + noisy + ", denoised " + denoised);
        // The contrast: the mean of the dark squares and of the bright ones, as the truth has them.
        double dark = 0, bright = 0;
        int nd = 0, nb = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if (((x / 3) + (y / 3)) % 2 == 0) { dark += out.get(x, y, 1); nd++; } else { bright += out.get(x, y, 1); nb++; }
            }
        }
        assertEquals(0.15 * 0.8, dark / nd, 0.01);
        assertEquals(0.85 * 0.8, bright / nb, 0.01);
    }

    @Test
    void anAlbedoEdgeStaysSharp() throws InterruptedException {
        Synthetic s = synthetic((x, y) -> x < W / 2 ? 0 : 1, new double[] {0.2, 0.8}, (x, y) -> 0, new double[] {1}, SIGMA, 3);
        FrameBuffer out = new Denoiser().denoise(s.noisy(), s.features(), 2);
        assertEdgeKept(s, out, W / 2 - 1, W / 2);
    }

    @Test
    void aNormalEdgeIsNotBlurredAcross() throws InterruptedException {
        // Two faces of a box, one albedo, lit differently: only the normal tells them apart.
        Synthetic s = synthetic((x, y) -> 0, new double[] {0.7}, (x, y) -> x < W / 2 ? 0 : 1, new double[] {0.3, 0.9}, SIGMA, 4);
        FrameBuffer out = new Denoiser().denoise(s.noisy(), s.features(), 2);
        assertEdgeKept(s, out, W / 2 - 1, W / 2);
    }

    /**
     * Columns a and b, the two sides of an edge, keep their values along the edge: blurred
     * across it, a column would be shifted towards the other side's value by a large share of
     * the step (0.4 and more here); kept, its mean error is the residual noise's, near 0, and
     * its pixels are nearer the truth than the noisy ones.
     */
    private static void assertEdgeKept(Synthetic s, FrameBuffer out, int a, int b) {
        for (int col : new int[] {a, b}) {
            double bias = 0, err = 0, noisyErr = 0;
            for (int y = 0; y < H; y++) {
                for (int c = 0; c < 3; c++) {
                    double t = s.truth().get(col, y, c);
                    bias += out.get(col, y, c) - t;
                    err += Math.abs(out.get(col, y, c) - t);
                    noisyErr += Math.abs(s.noisy().get(col, y, c) - t);
                }
            }
            bias /= 3 * H;
            err /= 3 * H;
            noisyErr /= 3 * H;
            assertTrue(Math.abs(bias) < 0.01, "column " + col + ": shifted by " + bias);
            assertTrue(err < noisyErr / 2, "column " + col + ": mean error " + err + " (noisy " + noisyErr + ")");
        }
    }

    @Test
    void theResultDoesNotDependOnTheThreadCount() throws InterruptedException {
        Synthetic s = synthetic((x, y) -> ((x / 5) + (y / 7)) % 2, new double[] {0.3, 0.6}, (x, y) -> x < y ? 0 : 1, new double[] {0.5, 1}, SIGMA, 5);
        FrameBuffer one = new Denoiser().denoise(s.noisy(), s.features(), 1);
        FrameBuffer three = new Denoiser().denoise(s.noisy(), s.features(), 3);
        assertArrayEquals(one.data(), three.data());
    }

    @Test
    void refusesFeaturesOfAnotherSizeAndBadParameters() {
        Synthetic s = synthetic((x, y) -> 0, new double[] {0.5}, (x, y) -> 0, new double[] {1}, SIGMA, 6);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new Denoiser().denoise(new FrameBuffer(W + 1, H), s.features(), 1));
        assertEquals("features of 48x40 do not fit a 49x40 frame", e.getMessage());
        assertEquals("denoising radius must be 1 to 32 pixels, found 0",
                assertThrows(IllegalArgumentException.class, () -> new Denoiser(0, 2, 0.5)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> new Denoiser().denoise(s.noisy(), s.features(), 0));
    }

    @Test
    void aFrameTheHeapCannotDenoiseIsRefusedBeforeAnythingIsAllocated() {
        Synthetic s = synthetic((x, y) -> 0, new double[] {0.5}, (x, y) -> 0, new double[] {1}, SIGMA, 7);
        try (lt.spindulys.limits.HeapBudget.Scope cap = lt.spindulys.limits.HeapBudget.cap(Denoiser.bytes(W, H) / 2)) {
            lt.spindulys.limits.InsufficientMemoryException e = assertThrows(lt.spindulys.limits.InsufficientMemoryException.class,
                    () -> new Denoiser().denoise(s.noisy(), s.features(), 1));
            assertTrue(e.getMessage().startsWith("denoising the 48x40 frame needs "), e.getMessage());
        }
    }

    @Test
    void featureFramesAverageTimeStepsAndKeepTheVarianceOfTheMean() {
        FeatureFrame f = new FeatureFrame(2, 1);
        double[] v = new double[FeatureFrame.VALUES];
        java.util.Arrays.fill(v, 1);
        f.put(1, 0, v, false, 1);
        java.util.Arrays.fill(v, 3);
        f.put(1, 0, v, true, 2);
        assertEquals(2, f.get(1, 0, FeatureFrame.ALBEDO));
        assertEquals(1, f.get(1, 0, FeatureFrame.VARIANCE)); // (1 + 3) / 2^2
        assertEquals(0, f.get(0, 0, FeatureFrame.NORMAL));
    }
}
