package lt.spindulys.render;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;
import java.util.Optional;

import lt.spindulys.denoise.FeatureFrame;
import lt.spindulys.image.AovFrame;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageFormat;
import lt.spindulys.image.ImageWriter;
import lt.spindulys.image.PixelRegion;
import lt.spindulys.image.TileFile;
import lt.spindulys.scene.RenderSettings;

/**
 * A finished render: the frame in linear floating point, the render passes the scene asked for,
 * what it cost, and the settings it was made with, so that it can be shown or written without
 * restating them (8-bit images are sRGB-encoded exactly when the scene's settings say so).
 * Made by {@link Renderer} and {@link RenderJob}; the frame is shared, not copied.
 */
public final class RenderResult {
    private final RenderSettings settings;
    private final FrameBuffer frame;
    private final AovFrame passes;
    private final RenderStats stats;
    private final double loadSeconds, buildSeconds;
    private final PixelRegion region;
    /** The animation frame rendered, or null for a still: recorded in a tile's placement. */
    private final Integer animationFrame;
    private final java.util.List<String> subdivision, structures;
    /** The denoiser's features (null: not gathered), the frame before denoising (null: not denoised). */
    private final FeatureFrame features;
    private final FrameBuffer noisy;
    private final boolean writeNoisy;
    private final double denoiseSeconds;

    RenderResult(RenderSettings settings, FrameBuffer frame, AovFrame passes, RenderStats stats, java.util.List<String> subdivision,
                 java.util.List<String> structures) {
        this(settings, frame, passes, stats, subdivision, structures, 0, 0);
    }

    private RenderResult(RenderSettings settings, FrameBuffer frame, AovFrame passes, RenderStats stats, java.util.List<String> subdivision,
                         java.util.List<String> structures, double loadSeconds, double buildSeconds) {
        this(settings, frame, passes, stats, subdivision, structures, loadSeconds, buildSeconds, null, null, null, null, false, 0);
    }

    private RenderResult(RenderSettings settings, FrameBuffer frame, AovFrame passes, RenderStats stats, java.util.List<String> subdivision,
                         java.util.List<String> structures, double loadSeconds, double buildSeconds, PixelRegion region,
                         Integer animationFrame, FeatureFrame features, FrameBuffer noisy, boolean writeNoisy, double denoiseSeconds) {
        this.features = features;
        this.noisy = noisy;
        this.writeNoisy = writeNoisy;
        this.denoiseSeconds = denoiseSeconds;
        this.region = region;
        this.animationFrame = animationFrame;
        this.subdivision = java.util.List.copyOf(subdivision);
        this.structures = java.util.List.copyOf(structures);
        this.settings = Objects.requireNonNull(settings);
        this.frame = Objects.requireNonNull(frame);
        this.passes = passes;
        this.stats = Objects.requireNonNull(stats);
        this.loadSeconds = loadSeconds;
        this.buildSeconds = buildSeconds;
    }

    /** This result with the times a job spent before rendering. */
    RenderResult withTimes(double load, double build) {
        return new RenderResult(settings, frame, passes, stats, subdivision, structures, load, build, region, animationFrame,
                features, noisy, writeNoisy, denoiseSeconds);
    }

    /** This result as the render of {@code part} of the frame its settings describe (null: a render of the frame, not of a region). */
    RenderResult inRegion(PixelRegion part) {
        return new RenderResult(settings, frame, passes, stats, subdivision, structures, loadSeconds, buildSeconds, part, animationFrame,
                features, noisy, writeNoisy, denoiseSeconds);
    }

    /** This result as the render of animation frame {@code n} (null: a still). */
    RenderResult ofFrame(Integer n) {
        return new RenderResult(settings, frame, passes, stats, subdivision, structures, loadSeconds, buildSeconds, region, n,
                features, noisy, writeNoisy, denoiseSeconds);
    }

    /** This result with the denoiser's features gathered beside the frame (null: none). */
    RenderResult withFeatures(FeatureFrame f) {
        return new RenderResult(settings, frame, passes, stats, subdivision, structures, loadSeconds, buildSeconds, region, animationFrame,
                f, noisy, writeNoisy, denoiseSeconds);
    }

    /**
     * This result with {@code denoised} as its frame and the frame as it was kept as the noisy
     * one, written beside the image ({@link #noisyFileBeside}) when {@code writeNoisy}.
     */
    RenderResult denoised(FrameBuffer denoised, boolean writeNoisy, double seconds) {
        return new RenderResult(settings, denoised, passes, stats, subdivision, structures, loadSeconds, buildSeconds, region, animationFrame,
                features, frame, writeNoisy, seconds);
    }

    /**
     * The denoiser's features, when the render gathered them ({@link RenderJob#denoise}).
     *
     * @return the features, or empty
     */
    public Optional<FeatureFrame> features() { return Optional.ofNullable(features); }

    /**
     * The frame as rendered, before denoising, when it was denoised; {@link #frame()} is then the denoised one.
     *
     * @return the noisy frame, or empty when the frame was not denoised
     */
    public Optional<FrameBuffer> noisy() { return Optional.ofNullable(noisy); }

    /**
     * Whether {@link #write(Path)} writes the noisy frame beside the denoised one.
     *
     * @return true for a denoised render whose noisy frame was kept
     */
    public boolean writesNoisy() { return writeNoisy && noisy != null; }

    /**
     * Seconds the denoiser took (0 when the frame was not denoised).
     *
     * @return seconds, at least 0
     */
    public double denoiseSeconds() { return denoiseSeconds; }

    /**
     * The file the noisy frame is written to beside {@code out}: {@code .noisy} before its
     * extension, so {@code out.png} gives {@code out.noisy.png} (same format, no passes).
     *
     * @param out the image's path
     * @return the noisy image's path
     */
    public static Path noisyFileBeside(Path out) {
        String name = out.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return out.resolveSibling(dot > 0 ? name.substring(0, dot) + ".noisy" + name.substring(dot) : name + ".noisy");
    }

    /**
     * The part of the frame rendered, when one was asked for ({@link RenderJob#region},
     * {@link RenderJob#tile}): {@link #frame()} is then the region's size and {@link #write(Path)}
     * writes a tile ({@link TileFile}), even when the region is the whole frame.
     *
     * @return the region, or empty for a render of the frame
     */
    public Optional<PixelRegion> region() { return Optional.ofNullable(region); }

    /**
     * One line per adaptive subdivision tessellation of the scene (see
     * {@code Scene.adaptiveStatistics()}): method, levels, patches built, cache hits, misses,
     * evictions, peak bytes and the histogram of levels used, as they stood when the render ended.
     *
     * @return the lines, empty when the scene has no adaptive surface
     */
    public java.util.List<String> subdivisionStatistics() { return subdivision; }

    /**
     * One line per triangle mesh of the scene with a hierarchy over its triangles (see
     * {@code Scene.structureStatistics()}): its name, triangle count and the tree's SAH cost.
     *
     * @return the lines, empty when no mesh has a hierarchy
     */
    public java.util.List<String> structureStatistics() { return structures; }

    /**
     * The frame: linear RGB doubles, unclamped (what a PFM file holds).
     *
     * @return the frame buffer, shared
     */
    public FrameBuffer frame() { return frame; }

    /**
     * The frame as an 8-bit RGB image, encoded as the scene's settings say ({@link RenderSettings#srgb()}):
     * the pixels a PNG written by {@link #write(Path)} holds. A new image each call.
     *
     * @return a {@code TYPE_INT_RGB} image of the frame
     */
    public BufferedImage image() { return frame.toBufferedImage(settings.srgb()); }

    /**
     * The render passes the settings asked for ({@link RenderSettings#aovs()}), or empty when they asked for none.
     *
     * @return the passes, or empty
     */
    public Optional<AovFrame> passes() { return Optional.ofNullable(passes); }

    /**
     * Rays traced by kind and the wall time of the render itself.
     *
     * @return the render's statistics
     */
    public RenderStats stats() { return stats; }

    /**
     * Seconds a {@link RenderJob} spent reading the scene file (0 when it was given a scene).
     *
     * @return seconds, at least 0
     */
    public double loadSeconds() { return loadSeconds; }

    /**
     * Seconds a {@link RenderJob} spent building the scene (0 when it was given a built scene).
     *
     * @return seconds, at least 0
     */
    public double buildSeconds() { return buildSeconds; }

    /**
     * The settings the frame was rendered with (size, samples, sRGB, passes, ...).
     *
     * @return the settings
     */
    public RenderSettings settings() { return settings; }

    /**
     * Image width in pixels.
     *
     * @return the width, at least 1
     */
    public int width() { return frame.width(); }

    /**
     * Image height in pixels.
     *
     * @return the height, at least 1
     */
    public int height() { return frame.height(); }

    /**
     * Writes the image to {@code out} in the format its extension names (.png, .jpg/.jpeg, .tga,
     * .pfm, .exr), sRGB-encoded as the scene says, with each render pass beside it
     * ({@link lt.spindulys.image.Aov#filesBeside}) or, in an .exr, as its channels, and the noisy
     * frame of a denoised render when it was kept ({@link #noisyFileBeside}); all files are written atomically as one group,
     * so a failure leaves none of the new files and every old one. The render of a
     * {@link #region()} is written as a PNG tile that records its place ({@link TileFile}).
     *
     * @param out the image file
     * @throws IllegalArgumentException if the extension names no supported format
     * @throws IOException if a file cannot be written (the message names it)
     */
    public void write(Path out) throws IOException {
        write(out, ImageOptions.DEFAULT.jpegQuality());
    }

    /**
     * {@link #write(Path)} with a JPEG quality.
     *
     * @param out         the image file
     * @param jpegQuality in [0, 1], 1 best; other formats ignore it
     * @throws IllegalArgumentException if the quality is outside [0, 1] or the extension names no format
     * @throws IOException if a file cannot be written
     */
    public void write(Path out, double jpegQuality) throws IOException {
        write(out, new ImageOptions(settings.srgb(), jpegQuality));
    }

    /**
     * {@link #write(Path)} with encoding options; the sRGB encoding is the scene's whatever
     * {@code options} say.
     *
     * @param out     the image file
     * @param options the JPEG quality and the OpenEXR precision and compression
     * @throws IllegalArgumentException if the extension names no supported format
     * @throws IOException if a file cannot be written
     */
    public void write(Path out, ImageOptions options) throws IOException {
        ImageOptions opts = options.withSrgb(settings.srgb());
        if (region == null) {
            ImageWriter.write(frame, out, opts, passes, writeNoisy && noisy != null ? java.util.Map.of(noisyFileBeside(out), noisy) : java.util.Map.of());
            return;
        }
        checkTileOutput(out);
        ImageWriter.writeAtomically(out, TileFile.encoder(frame, opts, new TileFile.Placement(region, settings.width(), settings.height(), animationFrame)));
    }

    /**
     * Refuses an output other than PNG for a region: the tile's placement is kept in a PNG chunk.
     *
     * @param out the image file a region is to be written to
     * @throws IllegalArgumentException if its extension is not .png
     */
    public static void checkTileOutput(Path out) {
        if (ImageWriter.checkFormat(out) != ImageFormat.PNG) {
            throw new IllegalArgumentException("a region of a frame is written as a PNG tile (its place in the frame is recorded in the file), so "
                    + out + " must end in .png");
        }
    }
}
