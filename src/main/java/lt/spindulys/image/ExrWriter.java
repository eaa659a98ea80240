package lt.spindulys.image;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.zip.Deflater;

/**
 * Writes a frame, and its render passes as further channels, as a single-part scanline OpenEXR
 * 2.0 file, following the OpenEXR file layout: the magic number 20000630, version 2 with no
 * flags, the required header attributes, the offset table and the line blocks, all little-endian.
 *
 * <p>Channels, in the alphabetical (byte) order the format requires: {@code A} (always 1: the
 * frame has no coverage), {@code B}, {@code G}, {@code R}; with the normal pass {@code Normal.X},
 * {@code Normal.Y}, {@code Normal.Z}; with the depth pass {@code Z}, OpenEXR's own name for
 * depth, +Infinity where nothing was hit; with the object pass {@code IndexOB.X}, the object's
 * id + 1 and 0 for the background, exact as a float; with the albedo pass {@code Albedo.B},
 * {@code Albedo.G}, {@code Albedo.R}; with the noise pass {@code Samples.X} (the samples a
 * pixel took) and {@code Noise.X} (its estimated relative error). The names are Blender's: its loader shows
 * the passes as Combined, Depth, Normal and IndexOB (as its own renders name them), and Nuke
 * and OpenImageIO read {@code Z} as depth and each {@code layer.channel} as a layer. Colour,
 * normal and albedo follow {@link ImageOptions#exrPrecision()}; depth, object id and noise are
 * always FLOAT.
 *
 * <p>With {@link ExrCompression#ZIP} or {@link ExrCompression#ZIPS} each block's bytes are split
 * into the even-indexed and the odd-indexed ones, each byte replaced by its difference from the
 * one before plus 128 (OpenEXR's predictor), and the result deflated as a zlib stream; a block
 * that would not shrink is stored raw, as the format allows and readers expect.
 */
final class ExrWriter {
    private static final int MAGIC = 20000630;
    private static final int PIXEL_TYPE_HALF = 1, PIXEL_TYPE_FLOAT = 2;
    /** Largest finite half, and its bits. */
    private static final double MAX_HALF = 65504;
    private static final int MAX_HALF_BITS = 0x7BFF;

    private ExrWriter() {}

    /** The value of a channel at a pixel index (row-major, top row first). */
    @FunctionalInterface
    private interface Values {
        double at(int pixel);
    }

    private record Channel(String name, boolean half, Values values) {
        int bytes() { return half ? 2 : 4; }
    }

    /**
     * What writes {@code fb} (and the passes of {@code aovs}, if not null) to a stream. The
     * object ids are checked now, before anything is written.
     *
     * @param fb   the image; its values are written linear, as they are
     * @param aovs the passes to add as channels, or null
     * @param opts the precision and compression
     * @return the body that writes the file into a stream
     * @throws IllegalStateException if an object id does not fit 24 bits
     * @throws IllegalArgumentException if the passes are not the image's size
     */
    static ImageWriter.IoConsumer<OutputStream> encoder(FrameBuffer fb, AovFrame aovs, ImageOptions opts) {
        int w = fb.width(), h = fb.height();
        if (aovs != null && (aovs.width() != w || aovs.height() != h)) {
            throw new IllegalArgumentException("passes of " + aovs.width() + "x" + aovs.height() + " for an image of " + w + "x" + h);
        }
        boolean half = opts.exrPrecision() == ExrPrecision.HALF;
        double[] rgb = fb.data();
        List<Channel> channels = new ArrayList<>();
        channels.add(new Channel("A", half, p -> 1));
        channels.add(new Channel("B", half, p -> rgb[3 * p + 2]));
        channels.add(new Channel("G", half, p -> rgb[3 * p + 1]));
        channels.add(new Channel("R", half, p -> rgb[3 * p]));
        if (aovs != null) {
            if (aovs.passes().contains(Aov.NORMAL)) {
                double[] n = aovs.normalData();
                channels.add(new Channel("Normal.X", half, p -> n[3 * p]));
                channels.add(new Channel("Normal.Y", half, p -> n[3 * p + 1]));
                channels.add(new Channel("Normal.Z", half, p -> n[3 * p + 2]));
            }
            if (aovs.passes().contains(Aov.DEPTH)) {
                double[] d = aovs.depthData();
                channels.add(new Channel("Z", false, p -> d[p]));
            }
            if (aovs.passes().contains(Aov.ALBEDO)) {
                double[] a = aovs.albedoData();
                channels.add(new Channel("Albedo.R", half, p -> a[3 * p]));
                channels.add(new Channel("Albedo.G", half, p -> a[3 * p + 1]));
                channels.add(new Channel("Albedo.B", half, p -> a[3 * p + 2]));
            }
            if (aovs.passes().contains(Aov.OBJECT)) {
                int[] codes = aovs.objectCodes();
                channels.add(new Channel("IndexOB.X", false, p -> codes[p]));
            }
            if (aovs.passes().contains(Aov.NOISE)) {
                // Float: sample counts above 2048 are not exact in half precision.
                double[] n = aovs.noiseData();
                channels.add(new Channel("Samples.X", false, p -> n[2 * p]));
                channels.add(new Channel("Noise.X", false, p -> n[2 * p + 1]));
            }
        }
        // Readers rely on the order: OpenEXR keeps channel lists sorted by strcmp.
        channels.sort(Comparator.comparing(Channel::name));
        return out -> write(w, h, channels, opts.exrCompression(), out);
    }

    private static void write(int w, int h, List<Channel> channels, ExrCompression compression, OutputStream out)
            throws IOException {
        Bytes header = new Bytes();
        header.int32(MAGIC);
        header.int32(2); // version 2; single-part scanline, names under 32 bytes: no flags
        Bytes chlist = new Bytes();
        for (Channel c : channels) {
            chlist.string(c.name());
            chlist.int32(c.half() ? PIXEL_TYPE_HALF : PIXEL_TYPE_FLOAT);
            chlist.int32(0); // pLinear and three reserved bytes
            chlist.int32(1); // x sampling
            chlist.int32(1); // y sampling
        }
        chlist.write(0);
        header.attribute("channels", "chlist", chlist);
        header.attribute("compression", "compression", new Bytes().byte8(compression.code()));
        Bytes window = new Bytes();
        window.int32(0);
        window.int32(0);
        window.int32(w - 1);
        window.int32(h - 1);
        header.attribute("dataWindow", "box2i", window);
        header.attribute("displayWindow", "box2i", window);
        header.attribute("lineOrder", "lineOrder", new Bytes().byte8(0)); // INCREASING_Y
        header.attribute("pixelAspectRatio", "float", new Bytes().float32(1));
        header.attribute("screenWindowCenter", "v2f", new Bytes().float32(0).float32(0));
        header.attribute("screenWindowWidth", "float", new Bytes().float32(1));
        header.write(0);

        int lines = compression.linesPerBlock();
        int blocks = (h + lines - 1) / lines;
        int bytesPerLine = 0;
        for (Channel c : channels) bytesPerLine += w * c.bytes();
        byte[] raw = new byte[bytesPerLine * Math.min(lines, h)];
        header.writeTo(out);
        if (compression == ExrCompression.NONE) {
            // Every block's size is known: the offset table is written first and each block as it is made.
            Bytes table = new Bytes();
            long offset = header.size() + 8L * blocks;
            for (int b = 0; b < blocks; b++) {
                table.int64(offset);
                offset += 8 + (long) bytesPerLine * (Math.min(h, (b + 1) * lines) - b * lines);
            }
            table.writeTo(out);
            for (int b = 0; b < blocks; b++) {
                int y0 = b * lines;
                writeBlock(out, y0, raw, fillBlock(raw, w, y0, Math.min(h, y0 + lines), channels));
            }
            return;
        }
        // The offset table precedes the blocks, whose compressed sizes are known only once they are made.
        byte[][] encoded = new byte[blocks][];
        byte[] reordered = new byte[raw.length];
        Deflater deflater = new Deflater();
        try {
            for (int b = 0; b < blocks; b++) {
                int y0 = b * lines;
                encoded[b] = zip(raw, fillBlock(raw, w, y0, Math.min(h, y0 + lines), channels), reordered, deflater);
            }
        } finally {
            deflater.end();
        }
        Bytes table = new Bytes();
        long offset = header.size() + 8L * blocks;
        for (int b = 0; b < blocks; b++) {
            table.int64(offset);
            offset += 8 + encoded[b].length;
        }
        table.writeTo(out);
        for (int b = 0; b < blocks; b++) writeBlock(out, b * lines, encoded[b], encoded[b].length);
    }

    /** One line block: its first line, its size and its bytes. */
    private static void writeBlock(OutputStream out, int firstLine, byte[] data, int size) throws IOException {
        byte[] prefix = {
            (byte) firstLine, (byte) (firstLine >>> 8), (byte) (firstLine >>> 16), (byte) (firstLine >>> 24),
            (byte) size, (byte) (size >>> 8), (byte) (size >>> 16), (byte) (size >>> 24)};
        out.write(prefix);
        out.write(data, 0, size);
    }

    /** Lays out lines y0 to y1 - 1: per line, each channel's values left to right. Returns the byte count. */
    private static int fillBlock(byte[] raw, int w, int y0, int y1, List<Channel> channels) {
        int i = 0;
        for (int y = y0; y < y1; y++) {
            for (Channel c : channels) {
                for (int p = y * w, end = p + w; p < end; p++) {
                    double v = c.values().at(p);
                    int bits;
                    if (c.half()) {
                        bits = halfBits(v);
                        raw[i++] = (byte) bits;
                        raw[i++] = (byte) (bits >>> 8);
                    } else {
                        bits = Float.floatToRawIntBits((float) v);
                        raw[i++] = (byte) bits;
                        raw[i++] = (byte) (bits >>> 8);
                        raw[i++] = (byte) (bits >>> 16);
                        raw[i++] = (byte) (bits >>> 24);
                    }
                }
            }
        }
        return i;
    }

    /** OpenEXR's ZIP encoding of {@code raw[0, size)}: reorder, predict, deflate; raw if that does not shrink it. */
    private static byte[] zip(byte[] raw, int size, byte[] reordered, Deflater deflater) {
        int even = 0, odd = (size + 1) / 2;
        for (int i = 0; i < size; i += 2) {
            reordered[even++] = raw[i];
            if (i + 1 < size) reordered[odd++] = raw[i + 1];
        }
        int previous = reordered[0];
        for (int i = 1; i < size; i++) {
            int current = reordered[i];
            reordered[i] = (byte) (current - previous + 128);
            previous = current;
        }
        deflater.reset();
        deflater.setInput(reordered, 0, size);
        deflater.finish();
        byte[] packed = new byte[size];
        int n = 0;
        while (!deflater.finished() && n < size) n += deflater.deflate(packed, n, size - n);
        // A block stored at its full size is taken by readers as uncompressed.
        if (!deflater.finished() || n >= size) return Arrays.copyOf(raw, size);
        return Arrays.copyOf(packed, n);
    }

    /**
     * The bits of the half nearest to {@code v}, ties to even, rounded once from the double (a
     * detour through float could round twice). Finite values beyond the half range are clamped
     * to +-65504; infinities stay infinite (depth's background) and NaN stays NaN (a quiet one).
     *
     * @param v the value
     * @return the half's 16 bits, in the low bits of the int
     */
    static int halfBits(double v) {
        if (Double.isNaN(v)) return 0x7E00;
        int sign = (Double.doubleToRawLongBits(v) < 0) ? 0x8000 : 0;
        double a = Math.abs(v);
        if (a == Double.POSITIVE_INFINITY) return sign | 0x7C00;
        if (a >= MAX_HALF) return sign | MAX_HALF_BITS;
        // Below 2^-14 a half counts units of 2^-24; 1024 units is the smallest normal's encoding.
        if (a < 0x1p-14) return sign | (int) Math.rint(a * 0x1p24);
        int exponent = Math.getExponent(a);
        // rint rounds ties to even; the scaling by a power of two is exact.
        int significand = (int) Math.rint(Math.scalb(a, 10 - exponent));
        if (significand == 2048) { // rounded up into the next binade
            significand = 1024;
            exponent++;
        }
        return sign | (exponent + 15) << 10 | (significand - 1024);
    }

    /** A little-endian byte buffer for the header. */
    private static final class Bytes extends ByteArrayOutputStream {
        Bytes int32(int v) {
            write(v);
            write(v >>> 8);
            write(v >>> 16);
            write(v >>> 24);
            return this;
        }

        Bytes int64(long v) {
            int32((int) v);
            return int32((int) (v >>> 32));
        }

        Bytes float32(float v) { return int32(Float.floatToRawIntBits(v)); }

        Bytes byte8(int v) {
            write(v);
            return this;
        }

        /** A null-terminated string. */
        void string(String s) {
            writeBytes(s.getBytes(StandardCharsets.US_ASCII));
            write(0);
        }

        void attribute(String name, String type, Bytes value) {
            string(name);
            string(type);
            int32(value.size());
            write(value.buf, 0, value.count);
        }
    }
}
