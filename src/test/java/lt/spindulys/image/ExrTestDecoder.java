package lt.spindulys.image;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.DataFormatException;
import java.util.zip.Inflater;

/**
 * A minimal reader of single-part scanline OpenEXR files with NONE, ZIPS or ZIP compression, for
 * the writer's round-trip tests: it follows the file layout independently of the writer and
 * fails on anything it does not expect.
 */
public final class ExrTestDecoder {
    /** One channel: its name, pixel type (1 half, 2 float) and values as floats, row-major, top row first. */
    public record Channel(String name, int pixelType, float[] values) {}

    /** A decoded file: header attributes by name (type and raw value), size, compression code and channels in file order. */
    public record Image(Map<String, String> attributeTypes, Map<String, byte[]> attributes, int width, int height,
                        int compression, List<Channel> channels) {
        /** The named channel. */
        public Channel channel(String name) {
            for (Channel c : channels) if (c.name().equals(name)) return c;
            throw new AssertionError("no channel " + name + " in " + channels.stream().map(Channel::name).toList());
        }
    }

    private ExrTestDecoder() {}

    /** Reads {@code file}. */
    public static Image read(Path file) throws IOException {
        ByteBuffer in = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.LITTLE_ENDIAN);
        if (in.getInt() != 20000630) throw new AssertionError("bad magic");
        if (in.getInt() != 2) throw new AssertionError("expected version 2 without flags");
        Map<String, String> types = new LinkedHashMap<>();
        Map<String, byte[]> values = new LinkedHashMap<>();
        while (true) {
            String name = string(in);
            if (name.isEmpty()) break;
            String type = string(in);
            byte[] value = new byte[in.getInt()];
            in.get(value);
            types.put(name, type);
            values.put(name, value);
        }
        ByteBuffer window = ByteBuffer.wrap(values.get("dataWindow")).order(ByteOrder.LITTLE_ENDIAN);
        int x0 = window.getInt(), y0 = window.getInt(), x1 = window.getInt(), y1 = window.getInt();
        int w = x1 - x0 + 1, h = y1 - y0 + 1;
        int compression = values.get("compression")[0];
        int lines = switch (compression) {
            case 0, 2 -> 1;
            case 3 -> 16;
            default -> throw new AssertionError("compression " + compression);
        };
        List<String> names = new ArrayList<>();
        List<Integer> pixelTypes = new ArrayList<>();
        ByteBuffer chlist = ByteBuffer.wrap(values.get("channels")).order(ByteOrder.LITTLE_ENDIAN);
        while (true) {
            String name = string(chlist);
            if (name.isEmpty()) break;
            names.add(name);
            pixelTypes.add(chlist.getInt());
            chlist.getInt();
            if (chlist.getInt() != 1 || chlist.getInt() != 1) throw new AssertionError("sampling");
        }
        float[][] data = new float[names.size()][w * h];
        int blocks = (h + lines - 1) / lines;
        long[] offsets = new long[blocks];
        for (int b = 0; b < blocks; b++) offsets[b] = in.getLong();
        for (int b = 0; b < blocks; b++) {
            in.position((int) offsets[b]);
            int y = in.getInt() - y0;
            int size = in.getInt();
            byte[] packed = new byte[size];
            in.get(packed);
            int linesHere = Math.min(lines, h - y);
            int rawSize = 0;
            for (int t : pixelTypes) rawSize += w * (t == 1 ? 2 : 4);
            rawSize *= linesHere;
            byte[] raw = size == rawSize ? packed : unzip(packed, rawSize);
            ByteBuffer r = ByteBuffer.wrap(raw).order(ByteOrder.LITTLE_ENDIAN);
            for (int line = y; line < y + linesHere; line++) {
                for (int c = 0; c < names.size(); c++) {
                    for (int x = 0; x < w; x++) {
                        data[c][line * w + x] = pixelTypes.get(c) == 1 ? halfToFloat(r.getShort() & 0xFFFF) : r.getFloat();
                    }
                }
            }
            if (r.hasRemaining()) throw new AssertionError("block " + b + " has bytes left over");
        }
        List<Channel> channels = new ArrayList<>();
        for (int c = 0; c < names.size(); c++) channels.add(new Channel(names.get(c), pixelTypes.get(c), data[c]));
        return new Image(types, values, w, h, compression, channels);
    }

    private static byte[] unzip(byte[] packed, int rawSize) throws IOException {
        Inflater inflater = new Inflater();
        byte[] t = new byte[rawSize];
        try {
            inflater.setInput(packed);
            int n = inflater.inflate(t);
            if (n != rawSize || !inflater.finished()) throw new AssertionError("inflated " + n + " of " + rawSize);
        } catch (DataFormatException e) {
            throw new IOException(e);
        } finally {
            inflater.end();
        }
        for (int i = 1; i < rawSize; i++) t[i] = (byte) (t[i - 1] + t[i] - 128);
        byte[] raw = new byte[rawSize];
        int half = (rawSize + 1) / 2;
        for (int i = 0; i < rawSize; i++) raw[i] = (i % 2 == 0) ? t[i / 2] : t[half + i / 2];
        return raw;
    }

    /** The float a half's bits stand for, exactly. */
    public static float halfToFloat(int h) {
        int exponent = (h >>> 10) & 0x1F, mantissa = h & 0x3FF;
        float magnitude;
        if (exponent == 0x1F) magnitude = mantissa == 0 ? Float.POSITIVE_INFINITY : Float.NaN;
        else if (exponent == 0) magnitude = mantissa * 0x1p-24f;
        else magnitude = (1 + mantissa / 1024f) * (float) Math.pow(2, exponent - 15);
        return (h & 0x8000) != 0 ? -magnitude : magnitude; // -0 too
    }

    private static String string(ByteBuffer in) {
        ByteArrayOutputStream s = new ByteArrayOutputStream();
        for (byte b; (b = in.get()) != 0; ) s.write(b);
        return s.toString(StandardCharsets.US_ASCII);
    }
}
