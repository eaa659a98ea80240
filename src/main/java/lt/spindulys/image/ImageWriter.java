package lt.spindulys.image;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

import lt.spindulys.files.AtomicFile;

/**
 * Writes a {@link FrameBuffer} to a file whose format is chosen by its extension (any case):
 * <ul>
 *   <li>{@code .tga}: uncompressed 24-bit true colour (image type 2), rows stored TOP-DOWN with
 *       descriptor bit 5 (0x20, "top-left origin") set, pixels as B, G, R, followed by the TGA 2.0
 *       footer;</li>
 *   <li>{@code .png}: 8-bit RGB through javax.imageio;</li>
 *   <li>{@code .jpg}/{@code .jpeg}: baseline JPEG through javax.imageio at
 *       {@link ImageOptions#jpegQuality()};</li>
 *   <li>{@code .pfm}: colour portable float map ("PF"), little-endian (scale -1), rows
 *       bottom-to-top as the format requires, linear 32-bit floats with no clamping;</li>
 *   <li>{@code .exr}: scanline OpenEXR, linear RGBA in halves or floats, uncompressed or ZIP
 *       ({@link ImageOptions#exrPrecision()}, {@link ImageOptions#exrCompression()}); render
 *       passes become channels of the same file ({@link ExrWriter}).</li>
 * </ul>
 * 8-bit formats are clamped and, if {@link ImageOptions#srgb()}, sRGB-encoded
 * ({@link FrameBuffer#toRgb8}).
 *
 * <p>All writes are atomic ({@link #writeAtomically}, through {@link AtomicFile}): readers of the target see either the old
 * file or the complete new one, never a partial image, and a failed write leaves the old file. An
 * image and its render passes ({@link #write(FrameBuffer, Path, ImageOptions, AovFrame)}) are
 * written as one group: all of them or none.
 */
public final class ImageWriter {
    private ImageWriter() {}

    /** Like {@link java.util.function.Consumer}, but may throw {@link IOException}. */
    @FunctionalInterface
    public interface IoConsumer<T> {
        /**
         * Takes the value.
         *
         * @param value the value
         * @throws IOException if writing fails
         */
        void accept(T value) throws IOException;
    }

    /**
     * The output format named by the extension of {@code out}; call it before rendering so that a
     * bad file name fails at once.
     *
     * @param out the output path
     * @return the format
     * @throws IllegalArgumentException e.g. "unsupported output format '.bmp' (expected .tga,
     *         .png, .jpg, .jpeg, .pfm or .exr)"
     */
    public static ImageFormat checkFormat(Path out) {
        return ImageFormat.of(out, "output");
    }

    /**
     * {@link #checkFormat} plus the checks {@link #writeAtomically} makes before writing: the
     * parent directory exists, {@code out} is not a directory, and a file can be created there
     * ({@link AtomicFile#checkWritable}: a trial file is created and deleted). Leaves nothing.
     *
     * @param out the output path
     * @return the format
     * @throws IOException if the file could not be written there
     */
    public static ImageFormat checkOutput(Path out) throws IOException {
        ImageFormat format = checkFormat(out);
        AtomicFile.checkWritable(out);
        return format;
    }

    /**
     * Encodes {@code fb} in the format named by the extension of {@code out} and writes it atomically.
     *
     * @param fb the image
     * @param out the output path; its extension names the format
     * @param opts the encoding options
     * @throws IOException if writing fails; {@code out} is then unchanged
     */
    public static void write(FrameBuffer fb, Path out, ImageOptions opts) throws IOException {
        write(fb, out, opts, null);
    }

    /**
     * Writes the image as {@link #write(FrameBuffer, Path, ImageOptions)} and, if {@code aovs} is
     * not null, its passes: in an OpenEXR output as channels of the same file, else each beside
     * it ({@link Aov#filesBeside}), all as one atomic group
     * ({@link AtomicFile#writeAll}): every file is encoded to a temporary file first and only then
     * are they renamed into place, so a failure in any of them leaves none of the new files and
     * every old one. The passes beside an image of another format:
     *
     * <ul>
     *   <li>depth: one-channel PFM ("Pf"), little-endian, bottom row first, 32-bit float
     *       distances, +Infinity where no object was hit;</li>
     *   <li>normal: three-channel PFM ("PF"), the x, y, z of the unit normal, 0 0 0 for the background;</li>
     *   <li>albedo: three-channel PFM ("PF"), r, g, b;</li>
     *   <li>object: 8-bit RGB PNG of id + 1 as a 24-bit integer, R the high byte, 0 0 0 for the
     *       background; never sRGB-encoded, whatever {@code opts} says.</li>
     * </ul>
     *
     * @param fb the image
     * @param out the output path; its extension names the format
     * @param opts the encoding options
     * @param aovs the passes, or null
     * @throws IOException if writing fails; no file is then changed
     * @throws IllegalStateException if an object id does not fit 24 bits (nothing is written)
     * @throws NonFinitePixelException if a pixel of the image or of the normal pass is NaN or
     *         infinite as a float (an internal error: nothing is written)
     */
    public static void write(FrameBuffer fb, Path out, ImageOptions opts, AovFrame aovs) throws IOException {
        write(fb, out, opts, aovs, java.util.Map.of());
    }

    /**
     * {@link #write(FrameBuffer, Path, ImageOptions, AovFrame)} with more images of the same
     * format in the same atomic group, such as the noisy frame beside a denoised one; each is
     * encoded as {@link #encoder} encodes it, without passes.
     *
     * @param fb the image
     * @param out the output path; its extension names the format
     * @param opts the encoding options
     * @param aovs the passes, or null
     * @param beside more images, by the path each is written to
     * @throws IOException if writing fails; no file is then changed
     */
    public static void write(FrameBuffer fb, Path out, ImageOptions opts, AovFrame aovs, java.util.Map<Path, FrameBuffer> beside) throws IOException {
        Objects.requireNonNull(fb, "fb");
        Objects.requireNonNull(opts, "opts");
        if (aovs != null && aovs.passes().contains(Aov.NORMAL)) checkFinite(aovs.width(), aovs.normalData(), 3);
        List<Path> files = new ArrayList<>();
        List<AtomicFile.Body> bodies = new ArrayList<>();
        for (java.util.Map.Entry<Path, FrameBuffer> e : beside.entrySet()) {
            IoConsumer<OutputStream> more = encoder(e.getValue(), e.getKey(), opts);
            files.add(e.getKey());
            bodies.add(more::accept);
        }
        if (checkFormat(out) == ImageFormat.EXR) {
            checkFinite(fb.width(), fb.data(), 3);
            // One file holds the image and its passes as channels: nothing is written beside it.
            IoConsumer<OutputStream> exr = ExrWriter.encoder(fb, aovs, opts);
            if (files.isEmpty()) {
                AtomicFile.write(out, exr::accept);
            } else {
                files.add(0, out);
                bodies.add(0, exr::accept);
                AtomicFile.writeAll(files, bodies);
            }
            return;
        }
        IoConsumer<OutputStream> image = encoder(fb, out, opts);
        files.add(0, out);
        bodies.add(0, image::accept);
        if (aovs != null) {
            for (Aov a : aovs.passes()) {
                files.add(a.fileBeside(out));
                switch (a) {
                    case DEPTH: bodies.add(os -> writeGreyPfm(aovs.width(), aovs.height(), aovs.depthData(), os)); break;
                    case NORMAL: bodies.add(os -> writePfm(aovs.normalImage(), os)); break;
                    case ALBEDO: bodies.add(os -> writePfm(aovs.albedoImage(), os)); break;
                    case OBJECT: {
                        int[] codes = aovs.objectCodes(); // checked before anything is written
                        bodies.add(os -> writeImageIo(aovs.width(), aovs.height(), codes, opts, "png", os));
                        break;
                    }
                    case NOISE: bodies.add(os -> writePfm(aovs.noiseImage(), os)); break;
                    default: throw new AssertionError(a);
                }
            }
        }
        AtomicFile.writeAll(files, bodies);
    }

    /**
     * What writes {@code fb} in the format {@code out}'s extension names, for a caller that writes
     * it together with other files in one atomic group (the output plugin writes its image, scene
     * and meshes so, as {@link #write(FrameBuffer, Path, ImageOptions, AovFrame)} writes passes). The checks of {@link #write(FrameBuffer, Path,
     * ImageOptions)} are made now, before anything is written.
     *
     * @param fb   the image
     * @param out  the output path; its extension names the format
     * @param opts the encoding options
     * @return the body that encodes the image into a stream
     * @throws IllegalArgumentException if the extension names no format, or a TGA is too large
     * @throws NonFinitePixelException  if a pixel is NaN or infinite as a float
     */
    public static IoConsumer<OutputStream> encoder(FrameBuffer fb, Path out, ImageOptions opts) {
        Objects.requireNonNull(fb, "fb");
        Objects.requireNonNull(opts, "opts");
        ImageFormat format = checkFormat(out);
        // The last line of defence: the scene's ranges keep pixels finite, so one that is not is a bug.
        checkFinite(fb.width(), fb.data(), 3);
        if (format == ImageFormat.TGA && (fb.width() > 0xFFFF || fb.height() > 0xFFFF)) {
            throw new IllegalArgumentException("TGA images are at most 65535x65535 pixels, got "
                    + fb.width() + "x" + fb.height());
        }
        return switch (format) {
            case TGA -> os -> writeTga(fb, opts.srgb(), os);
            case PNG -> os -> writeImageIo(fb.width(), fb.height(), fb.toRgb8(opts.srgb()), opts, "png", os);
            case JPEG -> os -> writeImageIo(fb.width(), fb.height(), fb.toRgb8(opts.srgb()), opts, "jpeg", os);
            case PFM -> os -> writePfm(fb, os);
            case EXR -> ExrWriter.encoder(fb, null, opts);
        };
    }

    /**
     * What writes 8-bit pixels as a PNG as they are (no encoding curve), for a picture made
     * directly in 8 bits, such as a legend, written in an atomic group.
     *
     * @param width  the width, at least 1
     * @param height the height, at least 1
     * @param rgb    {@code width * height} pixels 0xRRGGBB (higher bits ignored), rows from the top
     * @return the body that encodes the PNG into a stream
     */
    public static IoConsumer<OutputStream> pngEncoder(int width, int height, int[] rgb) {
        if (width < 1 || height < 1 || rgb.length != (long) width * height) {
            throw new IllegalArgumentException(rgb.length + " pixels do not make a " + width + "x" + height + " image");
        }
        return os -> writeImageIo(width, height, rgb, ImageOptions.DEFAULT, "png", os);
    }

    /**
     * Throws {@link NonFinitePixelException} for the first value (of {@code channels} per pixel,
     * rows of {@code width} pixels, top row first) that is NaN or infinite as a 32-bit float.
     */
    static void checkFinite(int width, double[] d, int channels) {
        for (int i = 0; i < d.length; i++) {
            if (!(Math.abs(d[i]) <= Float.MAX_VALUE)) {
                int pixel = i / channels;
                throw new NonFinitePixelException(pixel % width, pixel / width);
            }
        }
    }

    /**
     * {@link #checkOutput} for {@code out} and for the file of each pass in {@code aovs} beside
     * it. Leaves nothing.
     *
     * @param out the main output path
     * @param aovs the passes to be written beside it
     * @throws IOException if one of the files could not be written
     */
    public static void checkOutputs(Path out, Set<Aov> aovs) throws IOException {
        checkOutput(out);
        checkPassOutputs(out, aovs);
    }

    /**
     * The check of {@link #checkOutputs} for the passes' files alone, for a caller that has
     * already checked {@code out} itself. Leaves nothing.
     *
     * @param out the main output path
     * @param aovs the passes to be written beside it
     * @throws IOException if one of the files could not be written
     */
    public static void checkPassOutputs(Path out, Set<Aov> aovs) throws IOException {
        for (Path p : Aov.filesBeside(out, aovs)) AtomicFile.checkWritable(p);
    }

    /**
     * Writes a file atomically through {@link AtomicFile#write}: {@code body} writes into a new
     * temporary file {@code .spindulys-RANDOM.tmp} in the target's directory, which is flushed to
     * disk, closed and then renamed over {@code out}. If anything fails, including {@code body}
     * throwing, the temporary file is deleted and an existing {@code out} is left untouched.
     *
     * <p>{@code body} gets a buffered stream; closing it only flushes, so the body may use
     * try-with-resources on wrappers around it.
     *
     * @param out the file to write
     * @param body writes the content
     * @throws IOException if the parent directory is missing (the message names it), {@code out}
     *         is a directory, or writing or renaming fails
     */
    public static void writeAtomically(Path out, IoConsumer<OutputStream> body) throws IOException {
        Objects.requireNonNull(body, "body");
        AtomicFile.write(out, body::accept);
    }

    private static void writeTga(FrameBuffer fb, boolean srgb, OutputStream out) throws IOException {
        int w = fb.width(), h = fb.height();
        int[] rgb = fb.toRgb8(srgb);
        byte[] header = new byte[18];
        header[2] = 2;                   // uncompressed true-colour
        header[12] = (byte) w;
        header[13] = (byte) (w >>> 8);
        header[14] = (byte) h;
        header[15] = (byte) (h >>> 8);
        header[16] = 24;                 // bits per pixel
        header[17] = 0x20;               // top-left origin (rows top-down), no alpha bits
        out.write(header);
        byte[] row = new byte[3 * w];
        for (int y = 0; y < h; y++) {
            for (int x = 0, i = 0; x < w; x++) {
                int v = rgb[y * w + x];
                row[i++] = (byte) v;          // blue
                row[i++] = (byte) (v >>> 8);  // green
                row[i++] = (byte) (v >>> 16); // red
            }
            out.write(row);
        }
        // TGA 2.0 footer: no extension or developer area; the signature marks a "new" TGA file.
        out.write(new byte[8]);
        out.write("TRUEVISION-XFILE.\0".getBytes(StandardCharsets.US_ASCII));
    }

    /** Encodes packed 0xRRGGBB pixels (row-major, top row first) as they are. */
    private static void writeImageIo(int w, int h, int[] rgb, ImageOptions opts, String formatName, OutputStream out)
            throws IOException {
        BufferedImage img = FrameBuffer.rgbImage(w, h, rgb);

        Iterator<javax.imageio.ImageWriter> writers = ImageIO.getImageWritersByFormatName(formatName);
        if (!writers.hasNext()) throw new IOException("this Java runtime has no " + formatName + " encoder");
        javax.imageio.ImageWriter writer = writers.next();
        // An explicit in-memory stream: ImageIO's own stream factory may cache in a file under
        // java.io.tmpdir, and closing this one flushes without closing our stream.
        try (ImageOutputStream ios = new MemoryCacheImageOutputStream(out)) {
            writer.setOutput(ios);
            ImageWriteParam param = writer.getDefaultWriteParam();
            if (formatName.equals("jpeg")) {
                param.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
                param.setCompressionQuality((float) opts.jpegQuality());
            }
            writer.write(null, new IIOImage(img, null, null), param);
        } finally {
            writer.dispose();
        }
    }

    private static void writePfm(FrameBuffer fb, OutputStream out) throws IOException {
        int w = fb.width(), h = fb.height();
        double[] d = fb.data();
        out.write(("PF\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        ByteBuffer row = ByteBuffer.allocate(12 * w).order(ByteOrder.LITTLE_ENDIAN);
        for (int y = h - 1; y >= 0; y--) {   // PFM stores the bottom row first
            row.clear();
            for (int i = 3 * y * w, end = i + 3 * w; i < end; i++) row.putFloat((float) d[i]);
            out.write(row.array());
        }
    }

    /** One-channel PFM ("Pf") of {@code d} (w x h values, top row first), little-endian. */
    private static void writeGreyPfm(int w, int h, double[] d, OutputStream out) throws IOException {
        out.write(("Pf\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII));
        ByteBuffer row = ByteBuffer.allocate(4 * w).order(ByteOrder.LITTLE_ENDIAN);
        for (int y = h - 1; y >= 0; y--) {   // PFM stores the bottom row first
            row.clear();
            for (int i = y * w, end = i + w; i < end; i++) row.putFloat((float) d[i]);
            out.write(row.array());
        }
    }

    /** Hands a stream to a body that may close it without closing (or losing) the file underneath. */
}
