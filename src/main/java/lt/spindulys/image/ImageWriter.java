package lt.spindulys.image;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.io.BufferedOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Iterator;
import java.util.Objects;
import java.util.concurrent.ThreadLocalRandom;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.stream.ImageOutputStream;
import javax.imageio.stream.MemoryCacheImageOutputStream;

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
 *       bottom-to-top as the format requires, linear 32-bit floats with no clamping.</li>
 * </ul>
 * 8-bit formats are clamped and, if {@link ImageOptions#srgb()}, sRGB-encoded
 * ({@link FrameBuffer#toRgb8}).
 *
 * <p>All writes are atomic ({@link #writeAtomically}): readers of the target see either the old
 * file or the complete new one, never a partial image, and a failed write leaves the old file.
 */
public final class ImageWriter {
    private ImageWriter() {}

    /** Like {@link java.util.function.Consumer}, but may throw {@link IOException}. */
    @FunctionalInterface
    public interface IoConsumer<T> {
        void accept(T value) throws IOException;
    }

    /**
     * The output format named by the extension of {@code out}; call it before rendering so that a
     * bad file name fails at once.
     *
     * @throws IllegalArgumentException e.g. "unsupported output format '.bmp' (expected .tga,
     *         .png, .jpg, .jpeg or .pfm)"
     */
    public static ImageFormat checkFormat(Path out) {
        return ImageFormat.of(out, "output");
    }

    /**
     * {@link #checkFormat} plus the checks {@link #writeAtomically} makes before writing: the
     * parent directory exists and {@code out} is not a directory. Writes nothing.
     */
    public static ImageFormat checkOutput(Path out) throws IOException {
        ImageFormat format = checkFormat(out);
        checkTarget(out);
        return format;
    }

    /** Encodes {@code fb} in the format named by the extension of {@code out} and writes it atomically. */
    public static void write(FrameBuffer fb, Path out, ImageOptions opts) throws IOException {
        Objects.requireNonNull(fb, "fb");
        Objects.requireNonNull(opts, "opts");
        ImageFormat format = checkFormat(out);
        if (format == ImageFormat.TGA && (fb.width() > 0xFFFF || fb.height() > 0xFFFF)) {
            throw new IllegalArgumentException("TGA images are at most 65535x65535 pixels, got "
                    + fb.width() + "x" + fb.height());
        }
        switch (format) {
            case TGA: writeAtomically(out, os -> writeTga(fb, opts.srgb(), os)); break;
            case PNG: writeAtomically(out, os -> writeImageIo(fb, opts, "png", os)); break;
            case JPEG: writeAtomically(out, os -> writeImageIo(fb, opts, "jpeg", os)); break;
            case PFM: writeAtomically(out, os -> writePfm(fb, os)); break;
            default: throw new AssertionError(format);
        }
    }

    /**
     * Writes a file atomically: {@code body} writes into a new temporary file
     * {@code .NAME.RANDOM.tmp} in the target's directory, which is flushed to disk, closed and
     * then renamed over {@code out} (an atomic move where the file system supports it, else a
     * plain replacing move). If anything fails, including {@code body} throwing, the temporary
     * file is deleted and an existing {@code out} is left untouched.
     *
     * <p>{@code body} gets a buffered stream; closing it only flushes, so the body may use
     * try-with-resources on wrappers around it.
     *
     * @throws IOException if the parent directory is missing (the message names it), {@code out}
     *         is a directory, or writing or renaming fails
     */
    public static void writeAtomically(Path out, IoConsumer<OutputStream> body) throws IOException {
        Objects.requireNonNull(body, "body");
        Path dir = checkTarget(out);
        Path target = out.toAbsolutePath();
        String name = target.getFileName().toString();

        Path tmp = null;
        FileChannel channel = null;
        for (int attempt = 0; channel == null; attempt++) {
            Path candidate = dir.resolve("." + name + "." + Long.toHexString(ThreadLocalRandom.current().nextLong())
                    + ".tmp");
            try {
                // CREATE_NEW gives the usual default permissions (unlike createTempFile's 0600).
                channel = FileChannel.open(candidate, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                tmp = candidate;
            } catch (FileAlreadyExistsException e) {
                if (attempt >= 20) throw e;
            } catch (IOException e) {
                throw new IOException("cannot write '" + out + "': cannot create a temporary file in '" + dir
                        + "': " + e, e);
            }
        }

        try {
            try (FileChannel ch = channel) {
                OutputStream buffered = new BufferedOutputStream(Channels.newOutputStream(ch), 1 << 16);
                body.accept(new NonClosingStream(buffered));
                buffered.flush();
                // Data must be on disk before the rename makes it visible, or a crash could leave
                // an empty or partial file under the final name.
                ch.force(true);
            }
            keepPermissions(target, tmp);
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (Throwable t) {
            try {
                Files.deleteIfExists(tmp);
            } catch (IOException e) {
                t.addSuppressed(e);
            }
            throw t;
        }
        syncDirectory(dir);
    }

    /** Checks the parent directory of {@code out} and that {@code out} is not a directory; returns the parent. */
    private static Path checkTarget(Path out) throws IOException {
        Objects.requireNonNull(out, "out");
        Path target = out.toAbsolutePath();
        Path dir = target.getParent();
        if (dir == null || target.getFileName() == null) {
            throw new IOException("cannot write '" + out + "': not a file name");
        }
        // Name the directory as the user wrote it where possible, so the message is recognisable.
        Path shown = out.getParent() != null ? out.getParent() : dir;
        if (!Files.exists(dir)) {
            throw new IOException("cannot write '" + out + "': directory '" + shown + "' does not exist");
        }
        if (!Files.isDirectory(dir)) {
            throw new IOException("cannot write '" + out + "': '" + shown + "' is not a directory");
        }
        if (Files.isDirectory(target)) {
            throw new IOException("cannot write '" + out + "': it is a directory");
        }
        return dir;
    }

    /** A replaced file keeps its POSIX permissions, as it would if it were overwritten in place. */
    private static void keepPermissions(Path target, Path tmp) {
        try {
            if (Files.isRegularFile(target)) {
                Files.setPosixFilePermissions(tmp, Files.getPosixFilePermissions(target));
            }
        } catch (IOException | UnsupportedOperationException e) {
            // Cosmetic only: the new file then simply has default permissions.
        }
    }

    /** Makes the rename itself durable; not every platform can open a directory, so best effort. */
    private static void syncDirectory(Path dir) {
        try (FileChannel d = FileChannel.open(dir, StandardOpenOption.READ)) {
            d.force(true);
        } catch (IOException | RuntimeException e) {
            // The file is complete and in place; only durability across a power cut is weaker.
        }
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

    private static void writeImageIo(FrameBuffer fb, ImageOptions opts, String formatName, OutputStream out)
            throws IOException {
        int w = fb.width(), h = fb.height();
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) img.getRaster().getDataBuffer()).getData();
        System.arraycopy(fb.toRgb8(opts.srgb()), 0, pixels, 0, pixels.length);

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

    /** Hands a stream to a body that may close it without closing (or losing) the file underneath. */
    private static final class NonClosingStream extends FilterOutputStream {
        NonClosingStream(OutputStream out) { super(out); }

        @Override public void write(byte[] b, int off, int len) throws IOException { out.write(b, off, len); }

        @Override public void close() throws IOException { out.flush(); }
    }
}
