package lt.spindulys.image;

import java.util.Arrays;
import java.util.Collections;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;

/**
 * The render passes of one frame: per pixel the depth, the normal, the object id, the albedo and
 * the noise (samples taken, estimated error) that {@link Aov} describes, stored only for the passes
 * requested. Row-major, y = 0 the top row, like
 * {@link FrameBuffer}. Render threads may write disjoint pixels concurrently; no locking.
 */
public final class AovFrame {
    /** Largest object id + 1 that fits the 24 bits of the object pass. */
    public static final int MAX_OBJECT_CODE = 0xFFFFFF;

    private final int width, height;
    private final Set<Aov> passes;
    private final double[] depth, normal, albedo;
    private final int[] object;
    /** The noise pass: per pixel the samples taken and the estimated error, interleaved; null unless requested. */
    private final double[] noise;
    /** Whether a pass needs the extra ray through the pixel centre (every pass but the noise, which comes from the samples). */
    private final boolean centreRay;

    /**
     * A frame with every pixel at the background values (infinite depth, zero normal, no object).
     *
     * @param width pixels across
     * @param height pixels down
     * @param passes the passes to keep; memory is allocated for these only
     */
    public AovFrame(int width, int height, Set<Aov> passes) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1x1, got " + width + "x" + height);
        }
        // The normal pass holds three values per pixel, like a FrameBuffer, and has the same limit.
        if (3L * width * height > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("image size " + width + "x" + height + " is too large");
        }
        if (passes.isEmpty()) throw new IllegalArgumentException("no AOV requested");
        this.width = width;
        this.height = height;
        this.passes = Collections.unmodifiableSet(EnumSet.copyOf(passes));
        int n = width * height;
        depth = passes.contains(Aov.DEPTH) ? new double[n] : null;
        normal = passes.contains(Aov.NORMAL) ? new double[3 * n] : null;
        object = passes.contains(Aov.OBJECT) ? new int[n] : null;
        albedo = passes.contains(Aov.ALBEDO) ? new double[3 * n] : null;
        noise = passes.contains(Aov.NOISE) ? new double[2 * n] : null;
        centreRay = passes.stream().anyMatch(a -> a != Aov.NOISE && a != Aov.ALBEDO);
        if (depth != null) Arrays.fill(depth, Double.POSITIVE_INFINITY);
        if (object != null) Arrays.fill(object, -1);
    }

    /** {@return the width in pixels} */
    public int width() { return width; }

    /** {@return the height in pixels} */
    public int height() { return height; }

    /**
     * The passes this frame holds (unmodifiable, in {@link Aov} order).
     *
     * @return the passes
     */
    public Set<Aov> passes() { return passes; }

    /**
     * Whether any pass held comes from the extra camera ray through the pixel centre
     * ({@link #setHit}, {@link #setBackground}); the noise and albedo passes, which come from the
     * pixel's samples, do not.
     *
     * @return true if depth, normal or object is held
     */
    public boolean needsCentreRay() { return centreRay; }

    /**
     * Records the noise of pixel (x, y); nothing unless the noise pass was requested.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param samples the samples the pixel took
     * @param error the estimated relative error of its value
     */
    public void setNoise(int x, int y, int samples, double error) {
        if (noise == null) return;
        int p = index(x, y);
        noise[2 * p] = samples;
        noise[2 * p + 1] = error;
    }

    /**
     * The samples pixel (x, y) took.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @return the samples
     */
    public int noiseSamples(int x, int y) { return (int) require(noise, Aov.NOISE)[2 * index(x, y)]; }

    /**
     * The estimated relative error of pixel (x, y) when it stopped.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @return the error, at least 0
     */
    public double noiseError(int x, int y) { return require(noise, Aov.NOISE)[2 * index(x, y) + 1]; }

    /** The noise pass, samples and error interleaved per pixel, row-major, top row first (the backing array, not a copy). */
    double[] noiseData() { return require(noise, Aov.NOISE); }

    /** The noise pass as an image: samples in r, error in g, 0 in b. */
    FrameBuffer noiseImage() {
        FrameBuffer fb = new FrameBuffer(width, height);
        double[] d = fb.data(), n = require(noise, Aov.NOISE);
        for (int p = 0; p < width * height; p++) {
            d[3 * p] = n[2 * p];
            d[3 * p + 1] = n[2 * p + 1];
        }
        return fb;
    }

    /**
     * Records a hit at pixel (x, y): distance, unit normal, object id (GObject.id()).
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param distance distance along the ray, world units
     * @param nx normal x
     * @param ny normal y
     * @param nz normal z
     * @param objectId the object's id, at least 0
     */
    public void setHit(int x, int y, double distance, double nx, double ny, double nz, int objectId) {
        int p = index(x, y);
        if (depth != null) depth[p] = distance;
        if (normal != null) {
            normal[3 * p] = nx;
            normal[3 * p + 1] = ny;
            normal[3 * p + 2] = nz;
        }
        if (object != null) object[p] = objectId;
    }

    /**
     * Records that the pixel-centre ray of (x, y) hit nothing.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     */
    public void setBackground(int x, int y) {
        int p = index(x, y);
        if (depth != null) depth[p] = Double.POSITIVE_INFINITY;
        if (normal != null) normal[3 * p] = normal[3 * p + 1] = normal[3 * p + 2] = 0;
        if (object != null) object[p] = -1;
    }

    /**
     * Stores the albedo of pixel (x, y), averaged over its samples (see {@link Aov#ALBEDO}).
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param r red
     * @param g green
     * @param b blue
     */
    public void setAlbedo(int x, int y, double r, double g, double b) {
        int p = 3 * index(x, y);
        double[] a = require(albedo, Aov.ALBEDO);
        a[p] = r; a[p + 1] = g; a[p + 2] = b;
    }

    /**
     * One channel (0 = r, 1 = g, 2 = b) of the albedo pass.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param channel 0, 1 or 2
     * @return the albedo, 0 0 0 for the background
     */
    public double albedo(int x, int y, int channel) {
        Objects.checkIndex(channel, 3);
        return require(albedo, Aov.ALBEDO)[3 * index(x, y) + channel];
    }

    /** The albedo pass, three per pixel, row-major, top row first (the backing array, not a copy). */
    double[] albedoData() { return require(albedo, Aov.ALBEDO); }

    /** The albedo pass as an image. */
    FrameBuffer albedoImage() {
        FrameBuffer fb = new FrameBuffer(width, height);
        System.arraycopy(require(albedo, Aov.ALBEDO), 0, fb.data(), 0, albedo.length);
        return fb;
    }

    /**
     * Distance to the first hit, +Infinity for the background.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @return the depth, world units
     */
    public double depth(int x, int y) { return require(depth, Aov.DEPTH)[index(x, y)]; }

    /**
     * One component (0 = x, 1 = y, 2 = z) of the normal; 0 for the background.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param component 0, 1 or 2
     * @return the component, in [-1, 1]
     */
    public double normal(int x, int y, int component) {
        Objects.checkIndex(component, 3);
        return require(normal, Aov.NORMAL)[3 * index(x, y) + component];
    }

    /**
     * The id of the object hit, -1 for the background.
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @return the id, or -1
     */
    public int objectId(int x, int y) { return require(object, Aov.OBJECT)[index(x, y)]; }

    /** The single depth channel, row-major, top row first (the backing array, not a copy). */
    double[] depthData() { return require(depth, Aov.DEPTH); }

    /** The normal pass, three per pixel, row-major, top row first (the backing array, not a copy). */
    double[] normalData() { return require(normal, Aov.NORMAL); }

    /** The normal pass as an image (x, y, z in r, g, b). */
    FrameBuffer normalImage() {
        FrameBuffer fb = new FrameBuffer(width, height);
        System.arraycopy(require(normal, Aov.NORMAL), 0, fb.data(), 0, normal.length);
        return fb;
    }

    /**
     * The object pass as packed 0xRRGGBB values: id + 1, 0 for the background.
     *
     * @return one int per pixel, row-major, top row first
     * @throws IllegalStateException if an id + 1 does not fit 24 bits
     */
    public int[] objectCodes() {
        int[] ids = require(object, Aov.OBJECT);
        int[] out = new int[ids.length];
        for (int p = 0; p < ids.length; p++) {
            int code = ids[p] + 1;
            if (code < 0 || code > MAX_OBJECT_CODE) {
                throw new IllegalStateException("object id " + ids[p] + " does not fit the 24 bits of the object AOV");
            }
            out[p] = code;
        }
        return out;
    }

    private static <T> T require(T data, Aov pass) {
        if (data == null) throw new IllegalStateException("the " + pass.keyword() + " AOV was not requested");
        return data;
    }

    private int index(int x, int y) {
        Objects.checkIndex(x, width);
        Objects.checkIndex(y, height);
        return y * width + x;
    }
}
