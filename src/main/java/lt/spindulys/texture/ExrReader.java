package lt.spindulys.texture;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.math.Ranges;

/**
 * Reads OpenEXR images ({@code .exr}): single-part files, scanline or tiled (for mipmapped and
 * ripmapped files the full-resolution level), with HALF, FLOAT or UINT channels, compressed with
 * NONE, RLE, ZIPS, ZIP or PIZ. The R, G and B channels are read (a missing one is 0); a file
 * with none of them but a Y channel is read as grey; every other channel (alpha, layers such as
 * {@code diffuse.R}) is skipped. The image is the display window: pixels outside the data window
 * are black. Values are linear; negative and NaN values (resampling leaves small negatives in
 * many HDRIs) are read as 0, and values above {@link Ranges#MAX_COLOUR}, infinity included, are
 * clamped to it, as {@link HdrReader} does.
 *
 * <p>Refused, each in one line saying what was found: the lossy codecs (PXR24, B44, B44A,
 * DWAA, DWAB), multi-part and deep files, subsampled channels, and every inconsistency between
 * the header, the offset table and the data. The display and data windows are checked against
 * {@link TextureCache#MAX_PIXELS} and the heap before anything is allocated, and each block's
 * buffers are sized from the header, never from the data, so a hostile file cannot make the
 * reader allocate more than its declared image nor loop without end. Errors are
 * {@link IOException}s with a one-line reason; the caller names the file.
 */
final class ExrReader {
    private ExrReader() {}

    private static final int MAGIC = 20000630;
    private static final int FLAG_TILED = 0x200, FLAG_DEEP = 0x800, FLAG_MULTIPART = 0x1000;
    /** Most attributes in a header: far more than any writer emits, few enough to parse quickly. */
    private static final int MAX_ATTRIBUTES = 10_000;
    /** Most channels; real files have tens. */
    private static final int MAX_CHANNELS = 1024;

    static final int NONE = 0, RLE = 1, ZIPS = 2, ZIP = 3, PIZ = 4;
    private static final String[] CODEC_NAMES = {"NONE", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A", "DWAA", "DWAB"};
    static final int UINT = 0, HALF = 1, FLOAT = 2;

    /** One channel of the file, in the file's (alphabetical) order. */
    record ExrChannel(String name, int type) {
        int bytes() {
            return type == HALF ? 2 : 4;
        }
    }

    /**
     * Reads the file.
     *
     * @param file the file
     * @return the image (linear RGB, rows top-down)
     * @throws IOException if it cannot be read or is not an OpenEXR image this reader supports
     */
    static HdrReader.Image read(Path file) throws IOException {
        return read(InputFiles.readAllBytes(file, "OpenEXR file", 1));
    }

    /**
     * Reads an image held whole in {@code data}.
     *
     * @param data the file's bytes
     * @return the image (linear RGB, rows top-down)
     * @throws IOException if it is not an OpenEXR image this reader supports
     */
    static HdrReader.Image read(byte[] data) throws IOException {
        Bytes in = new Bytes(data);
        if (data.length < 8) throw new IOException("truncated OpenEXR file: " + data.length + " bytes, less than the 8 of the magic number and version");
        int magic = in.int32();
        if (magic != MAGIC) {
            throw new IOException(String.format("not an OpenEXR file: it starts with %02x %02x %02x %02x, expected 76 2f 31 01",
                    data[0] & 0xFF, data[1] & 0xFF, data[2] & 0xFF, data[3] & 0xFF));
        }
        int version = in.int32();
        if ((version & 0xFF) != 2) throw new IOException("unsupported OpenEXR version " + (version & 0xFF) + " (expected 2)");
        if ((version & FLAG_MULTIPART) != 0) throw new IOException("multi-part OpenEXR files are not supported (expected a single-part file; extract the part with exrmultipart -separate)");
        if ((version & FLAG_DEEP) != 0) throw new IOException("deep OpenEXR data are not supported (expected a flat image)");
        boolean tiled = (version & FLAG_TILED) != 0;

        List<ExrChannel> channels = null;
        int compression = -1;
        int[] dataWindow = null, displayWindow = null;
        int tileW = 0, tileH = 0;
        boolean tileDesc = false;
        for (int count = 0; ; count++) {
            if (count > MAX_ATTRIBUTES) throw new IOException("OpenEXR header has more than " + MAX_ATTRIBUTES + " attributes");
            String name = in.name("attribute name");
            if (name.isEmpty()) break;
            String type = in.name("attribute type of " + shown(name));
            int size = in.int32();
            if (size < 0 || size > in.remaining()) {
                throw new IOException("truncated OpenEXR header: attribute " + shown(name) + " says " + size + " bytes, " + in.remaining() + " remain");
            }
            int end = in.at + size;
            switch (name) {
                case "channels" -> channels = channels(in, end);
                case "compression" -> {
                    expectSize(name, size, 1);
                    compression = in.u8();
                }
                case "dataWindow" -> {
                    expectSize(name, size, 16);
                    dataWindow = new int[] {in.int32(), in.int32(), in.int32(), in.int32()};
                }
                case "displayWindow" -> {
                    expectSize(name, size, 16);
                    displayWindow = new int[] {in.int32(), in.int32(), in.int32(), in.int32()};
                }
                case "tiles" -> {
                    expectSize(name, size, 9);
                    tileW = in.int32();
                    tileH = in.int32();
                    tileDesc = true;
                }
                case "type" -> {
                    String t = new String(data, in.at, size, StandardCharsets.ISO_8859_1);
                    if (t.startsWith("deep")) throw new IOException("deep OpenEXR data are not supported (type " + shown(t) + "; expected a flat image)");
                }
                default -> { }
            }
            in.at = end;
        }
        if (channels == null) throw new IOException("bad OpenEXR header: no 'channels' attribute");
        if (compression < 0) throw new IOException("bad OpenEXR header: no 'compression' attribute");
        if (dataWindow == null || displayWindow == null) throw new IOException("bad OpenEXR header: no 'dataWindow' or 'displayWindow' attribute");
        if (compression >= CODEC_NAMES.length) throw new IOException("unknown OpenEXR compression " + compression + " (expected 0 to 9)");
        if (compression > PIZ) {
            throw new IOException(CODEC_NAMES[compression] + " compression is not supported (a lossy codec); re-save it with ZIP or PIZ");
        }
        if (tiled && !tileDesc) throw new IOException("bad OpenEXR header: a tiled file without a 'tiles' attribute");
        if (tiled && (tileW <= 0 || tileH <= 0)) throw new IOException("bad OpenEXR tile size " + tileW + "x" + tileH + " (expected positive)");

        long dataW = extent(dataWindow, 0, "data"), dataH = extent(dataWindow, 1, "data");
        long outW = extent(displayWindow, 0, "display"), outH = extent(displayWindow, 1, "display");
        TextureCache.checkSize(outW, outH);
        TextureCache.checkSize(dataW, dataH);
        int[] pick = pick(channels);

        // A block is the unit of compression: lines of the data window, or one tile.
        int blockW = tiled ? (int) Math.min(tileW, dataW) : (int) dataW;
        int blockH = tiled ? (int) Math.min(tileH, dataH) : Math.min(linesPerBlock(compression), (int) dataH);
        long pixelBytes = 0;
        for (ExrChannel c : channels) pixelBytes += c.bytes();
        long blockBytes = HeapBudget.product(blockW, blockH, pixelBytes);
        if (blockBytes > Integer.MAX_VALUE / 4) {
            throw new IOException("OpenEXR blocks of " + blockW + "x" + blockH + " pixels of " + channels.size() + " channels are too large (" + HeapBudget.format(blockBytes) + ")");
        }
        // The image, the mip chain, and each block raw, as decoded and as PIZ's 16-bit words.
        TextureCache.checkHeap(outW, outH, 4 * blockBytes, 12);

        long xBlocks = tiled ? (dataW + tileW - 1) / tileW : 1;
        long yBlocks = (dataH + blockH - 1) / blockH;
        long blocks = xBlocks * yBlocks;
        if (blocks * 8 > in.remaining()) {
            throw new IOException("truncated OpenEXR file: the offset table needs " + blocks + " entries (" + blocks * 8 + " bytes), " + in.remaining() + " bytes remain");
        }
        long[] offsets = new long[(int) blocks];
        for (int i = 0; i < blocks; i++) offsets[i] = in.int64();

        float[] rgb = new float[(int) (3 * outW * outH)];
        byte[] raw = new byte[(int) blockBytes];
        Decoder decoder = new Decoder(compression, (int) blockBytes);
        int[] channelAt = new int[channels.size()];
        for (int i = 0; i < offsets.length; i++) {
            long offset = offsets[i];
            int bx = (int) (i % xBlocks), by = (int) (i / xBlocks);
            if (offset < in.at || offset > data.length - (tiled ? 20 : 8)) {
                throw new IOException("bad OpenEXR offset table: " + blockName(tiled, bx, by) + " is at byte " + offset + ", outside the file's " + data.length + " bytes of pixel data");
            }
            Bytes chunk = new Bytes(data);
            chunk.at = (int) offset;
            int x0 = bx * (tiled ? tileW : 0), y0 = by * blockH;
            int w = (int) Math.min(blockW, dataW - x0), h = (int) Math.min(blockH, dataH - y0);
            if (tiled) {
                int tx = chunk.int32(), ty = chunk.int32(), lx = chunk.int32(), ly = chunk.int32();
                if (tx != bx || ty != by || lx != 0 || ly != 0) {
                    throw new IOException("bad OpenEXR file: " + blockName(tiled, bx, by) + " holds tile " + tx + "," + ty + " of level " + lx + "," + ly);
                }
            } else {
                int y = chunk.int32();
                if (y != dataWindow[1] + y0) {
                    throw new IOException("bad OpenEXR file: " + blockName(tiled, bx, by) + " starts at line " + y + ", expected " + (dataWindow[1] + y0));
                }
            }
            int size = chunk.int32();
            if (size < 0 || size > chunk.remaining()) {
                throw new IOException("truncated OpenEXR file: " + blockName(tiled, bx, by) + " says " + size + " bytes, " + chunk.remaining() + " remain");
            }
            int rawSize = (int) (w * h * pixelBytes);
            try {
                decoder.decode(data, chunk.at, size, raw, rawSize, channels, w, h);
            } catch (IOException e) {
                throw new IOException("corrupt OpenEXR " + CODEC_NAMES[compression] + " data in " + blockName(tiled, bx, by) + ": " + e.getMessage());
            }
            // raw holds, line by line, each channel's w samples in turn.
            for (int row = 0; row < h; row++) {
                int at = (int) (row * w * pixelBytes);
                for (int c = 0; c < channels.size(); c++) {
                    channelAt[c] = at;
                    at += w * channels.get(c).bytes();
                }
                long outY = (long) dataWindow[1] + y0 + row - displayWindow[1];
                if (outY < 0 || outY >= outH) continue;
                for (int x = 0; x < w; x++) {
                    long outX = (long) dataWindow[0] + x0 + x - displayWindow[0];
                    if (outX < 0 || outX >= outW) continue;
                    int q = (int) (3 * (outY * outW + outX));
                    for (int k = 0; k < 3; k++) {
                        int c = pick[k];
                        if (c >= 0) rgb[q + k] = sample(raw, channelAt[c], x, channels.get(c).type);
                    }
                }
            }
        }
        return new HdrReader.Image((int) outW, (int) outH, rgb);
    }

    private static String blockName(boolean tiled, int bx, int by) {
        return tiled ? "tile " + bx + "," + by : "line block " + by;
    }

    static int linesPerBlock(int compression) {
        return switch (compression) {
            case ZIP -> 16;
            case PIZ -> 32;
            default -> 1;
        };
    }

    /** For r, g and b the index of the channel read, or -1 (0); a Y-only file gives Y thrice. */
    private static int[] pick(List<ExrChannel> channels) throws IOException {
        int[] pick = {-1, -1, -1};
        int y = -1;
        for (int i = 0; i < channels.size(); i++) {
            switch (channels.get(i).name) {
                case "R" -> pick[0] = i;
                case "G" -> pick[1] = i;
                case "B" -> pick[2] = i;
                case "Y" -> y = i;
                default -> { }
            }
        }
        if (pick[0] < 0 && pick[1] < 0 && pick[2] < 0) {
            if (y < 0) {
                List<String> names = new ArrayList<>();
                for (ExrChannel c : channels) names.add(shown(c.name));
                String list = String.join(", ", names.size() > 8 ? names.subList(0, 8) : names) + (names.size() > 8 ? ", ..." : "");
                throw new IOException("OpenEXR file has no R, G, B or Y channel (it has " + (names.isEmpty() ? "none" : list) + ")");
            }
            pick[0] = pick[1] = pick[2] = y;
        }
        return pick;
    }

    private static float sample(byte[] raw, int channelAt, int x, int type) {
        float v;
        switch (type) {
            case HALF -> {
                int at = channelAt + 2 * x;
                v = halfToFloat(raw[at] & 0xFF | (raw[at + 1] & 0xFF) << 8);
            }
            case FLOAT -> v = Float.intBitsToFloat(int32(raw, channelAt + 4 * x));
            default -> v = (float) (int32(raw, channelAt + 4 * x) & 0xFFFFFFFFL);
        }
        if (!(v > 0)) return 0;  // negative or NaN
        return (float) Math.min(v, Ranges.MAX_COLOUR);
    }

    /** The IEEE 754 half-precision value with these 16 bits. */
    static float halfToFloat(int bits) {
        int sign = (bits & 0x8000) << 16, exponent = bits >> 10 & 0x1F, mantissa = bits & 0x3FF;
        if (exponent == 0x1F) return Float.intBitsToFloat(sign | 0x7F800000 | mantissa << 13);
        if (exponent == 0) {
            float v = mantissa * 0x1p-24f;  // subnormal
            return sign != 0 ? -v : v;
        }
        return Float.intBitsToFloat(sign | (exponent + 112) << 23 | mantissa << 13);
    }

    static int int32(byte[] b, int at) {
        return b[at] & 0xFF | (b[at + 1] & 0xFF) << 8 | (b[at + 2] & 0xFF) << 16 | (b[at + 3] & 0xFF) << 24;
    }

    private static long extent(int[] box, int axis, String which) throws IOException {
        long n = (long) box[axis + 2] - box[axis] + 1;
        if (n <= 0) {
            throw new IOException("bad OpenEXR " + which + " window (" + box[0] + "," + box[1] + ")-(" + box[2] + "," + box[3] + "): its maximum is below its minimum");
        }
        return n;
    }

    /** A name from the file as shown in messages: quoted, printable, at most 40 characters. */
    private static String shown(String s) {
        StringBuilder b = new StringBuilder("'");
        for (int i = 0; i < s.length(); i++) {
            if (i == 40) return b.append("...'").toString();
            char c = s.charAt(i);
            b.append(c >= 32 && c < 127 ? String.valueOf(c) : String.format("\\x%02x", (int) c));
        }
        return b.append('\'').toString();
    }

    private static void expectSize(String name, int size, int expected) throws IOException {
        if (size != expected) throw new IOException("bad OpenEXR attribute " + shown(name) + ": " + size + " bytes, expected " + expected);
    }

    private static List<ExrChannel> channels(Bytes in, int end) throws IOException {
        List<ExrChannel> list = new ArrayList<>();
        while (true) {
            if (in.at >= end) throw new IOException("bad OpenEXR channel list: it does not end with an empty name");
            String name = in.name("channel name");
            if (name.isEmpty()) break;
            if (list.size() >= MAX_CHANNELS) throw new IOException("OpenEXR file has more than " + MAX_CHANNELS + " channels");
            if (end - in.at < 16) throw new IOException("bad OpenEXR channel list: channel " + shown(name) + " is cut short");
            int type = in.int32();
            in.at += 4;  // pLinear and reserved bytes
            int xs = in.int32(), ys = in.int32();
            if (type < UINT || type > FLOAT) throw new IOException("bad OpenEXR channel " + shown(name) + ": pixel type " + type + " (expected 0 UINT, 1 HALF or 2 FLOAT)");
            if (xs != 1 || ys != 1) {
                throw new IOException("OpenEXR channel " + shown(name) + " is subsampled (" + xs + "x" + ys + "); only channels with a sample at every pixel are read");
            }
            list.add(new ExrChannel(name, type));
        }
        if (in.at != end) throw new IOException("bad OpenEXR channel list: it ends " + (end - in.at) + " bytes before its attribute");
        return list;
    }

    /** A read position in the file's bytes; every read is checked against the end. */
    private static final class Bytes {
        final byte[] b;
        int at;

        Bytes(byte[] b) {
            this.b = b;
        }

        int remaining() {
            return b.length - at;
        }

        private void need(int n) throws IOException {
            if (remaining() < n) throw new IOException("truncated OpenEXR file: it ends at byte " + b.length + " inside the header");
        }

        int u8() throws IOException {
            need(1);
            return b[at++] & 0xFF;
        }

        int int32() throws IOException {
            need(4);
            int v = ExrReader.int32(b, at);
            at += 4;
            return v;
        }

        long int64() throws IOException {
            need(8);
            long v = ExrReader.int32(b, at) & 0xFFFFFFFFL | (long) ExrReader.int32(b, at + 4) << 32;
            at += 8;
            return v;
        }

        /** A zero-terminated name of at most 255 bytes. */
        String name(String what) throws IOException {
            int start = at;
            while (true) {
                if (at >= b.length) throw new IOException("truncated OpenEXR header: it ends inside the " + what);
                if (b[at] == 0) break;
                if (at - start >= 255) throw new IOException("bad OpenEXR header: the " + what + " is longer than 255 bytes");
                at++;
            }
            String s = new String(b, start, at - start, StandardCharsets.ISO_8859_1);
            at++;
            return s;
        }
    }

    /** Undoes one codec on one block, into buffers sized once from the header. */
    private static final class Decoder {
        final int compression;
        final byte[] scratch;
        final Inflater inflater = new Inflater();
        final ExrPiz piz;

        Decoder(int compression, int maxBlockBytes) {
            this.compression = compression;
            this.scratch = compression == RLE || compression == ZIPS || compression == ZIP ? new byte[maxBlockBytes] : null;
            this.piz = compression == PIZ ? new ExrPiz(maxBlockBytes) : null;
        }

        /** Decodes {@code size} bytes at {@code data[at]} into {@code raw[0 .. rawSize)}. */
        void decode(byte[] data, int at, int size, byte[] raw, int rawSize, List<ExrChannel> channels, int w, int h) throws IOException {
            // Writers store a block as is when compressing it would not make it smaller.
            if (compression == NONE || size == rawSize) {
                if (size != rawSize) throw new IOException(size + " bytes, expected " + rawSize);
                System.arraycopy(data, at, raw, 0, rawSize);
                return;
            }
            if (size > rawSize) throw new IOException(size + " bytes, more than the " + rawSize + " it decodes to");
            switch (compression) {
                case RLE -> {
                    unRle(data, at, size, scratch, rawSize);
                    unPredict(scratch, raw, rawSize);
                }
                case ZIPS, ZIP -> {
                    inflate(data, at, size, scratch, rawSize);
                    unPredict(scratch, raw, rawSize);
                }
                default -> piz.decode(data, at, size, raw, rawSize, channels, w, h);
            }
        }

        private void inflate(byte[] data, int at, int size, byte[] out, int outSize) throws IOException {
            inflater.reset();
            inflater.setInput(data, at, size);
            int n = 0;
            try {
                while (n < outSize) {
                    int got = inflater.inflate(out, n, outSize - n);
                    if (got == 0) {
                        if (inflater.finished() || inflater.needsInput() || inflater.needsDictionary()) break;
                    }
                    n += got;
                }
                if (n == outSize && !inflater.finished() && inflater.inflate(new byte[1]) > 0) {
                    throw new IOException("the zlib stream holds more than the " + outSize + " bytes expected");
                }
            } catch (DataFormatException e) {
                throw new IOException("bad zlib stream (" + e.getMessage() + ")");
            }
            if (n != outSize) throw new IOException("the zlib stream holds " + n + " bytes, expected " + outSize);
        }

        /** OpenEXR's run-length code: a negative count -n is n literal bytes, a count n is n + 1 copies of the next byte. */
        private static void unRle(byte[] data, int at, int size, byte[] out, int outSize) throws IOException {
            int end = at + size, n = 0;
            while (at < end) {
                int count = data[at++];
                if (count < 0) {
                    count = -count;
                    if (count > end - at) throw new IOException("a literal run passes the end of the data");
                    if (count > outSize - n) throw new IOException("the runs hold more than the " + outSize + " bytes expected");
                    System.arraycopy(data, at, out, n, count);
                    at += count;
                    n += count;
                } else {
                    if (at >= end) throw new IOException("a repeat run passes the end of the data");
                    if (count + 1 > outSize - n) throw new IOException("the runs hold more than the " + outSize + " bytes expected");
                    java.util.Arrays.fill(out, n, n + count + 1, data[at++]);
                    n += count + 1;
                }
            }
            if (n != outSize) throw new IOException("the runs hold " + n + " bytes, expected " + outSize);
        }

        /** Undoes the delta predictor, then interleaves the two halves (low bytes first, high bytes second) back into place. */
        private static void unPredict(byte[] t, byte[] out, int n) {
            for (int i = 1; i < n; i++) t[i] = (byte) (t[i - 1] + t[i] - 128);
            int half = (n + 1) / 2;
            for (int i = 0, j = 0; i < n; i += 2, j++) {
                out[i] = t[j];
                if (i + 1 < n) out[i + 1] = t[half + j];
            }
        }
    }
}
