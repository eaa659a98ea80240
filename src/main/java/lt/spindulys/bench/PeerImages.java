package lt.spindulys.bench;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.texture.TgaReader;

/**
 * Reads the peers' images and compares them with ours, to make sure every renderer saw the same
 * view: the mean absolute difference of luma (Rec. 709 weights) of the sRGB-encoded 8-bit
 * values, and the share of pixels whose luma differs by more than 5 % of full scale. Embree and
 * Cycles jitter their one sample inside the pixel, we and POV-Ray take its centre, so edges
 * differ by a pixel's worth; a wrong view differs everywhere.
 */
final class PeerImages {
    private PeerImages() {}

    /** How two images differ: mean |luma difference| in 8-bit steps, and the share of pixels off by more than 5 %. */
    record Difference(double meanLuma, double shareOff) {}

    /**
     * Reads a binary PPM (P6, maxval 255) of exactly {@code width} x {@code height} pixels as
     * packed 0xRRGGBB, top row first; {@code linear} values (Embree's) are sRGB-encoded. The
     * size is checked against the expected one before any pixel memory is allocated.
     */
    static int[] readPpm(Path file, int width, int height, boolean linear) throws IOException {
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            if (in.read() != 'P' || in.read() != '6') throw new IOException(file + ": not a binary PPM (P6)");
            int w = header(in, file), h = header(in, file), max = header(in, file);
            if (w != width || h != height || max != 255) {
                throw new IOException(file + ": found " + w + "x" + h + " with maxval " + max + ", expected " + width + "x" + height + " with maxval 255");
            }
            byte[] px = in.readNBytes(3 * w * h);
            if (px.length != 3 * w * h) throw new IOException(file + ": truncated pixel data");
            int[] rgb = new int[w * h];
            for (int i = 0; i < rgb.length; i++) {
                int r = px[3 * i] & 0xFF, g = px[3 * i + 1] & 0xFF, b = px[3 * i + 2] & 0xFF;
                if (linear) {
                    r = FrameBuffer.to8(r / 255.0, true);
                    g = FrameBuffer.to8(g / 255.0, true);
                    b = FrameBuffer.to8(b / 255.0, true);
                }
                rgb[i] = r << 16 | g << 8 | b;
            }
            return rgb;
        }
    }

    /** One header number: skips white space and comments, then reads up to seven digits and one white space character. */
    private static int header(InputStream in, Path file) throws IOException {
        int c = in.read();
        while (c == '#' || Character.isWhitespace(c)) {
            if (c == '#') while (c != '\n' && c != -1) c = in.read();
            c = in.read();
        }
        int v = 0, digits = 0;
        while (c >= '0' && c <= '9' && digits < 7) {
            v = v * 10 + (c - '0');
            digits++;
            c = in.read();
        }
        if (digits == 0 || !Character.isWhitespace(c)) throw new IOException(file + ": bad PPM header");
        return v;
    }

    /** Reads a TGA (Blender's) of exactly {@code width} x {@code height} pixels as packed 0xRRGGBB, top row first. */
    static int[] readTga(Path file, int width, int height) throws IOException {
        TgaReader.Image img = TgaReader.read(file);
        if (img.width() != width || img.height() != height) {
            throw new IOException(file + ": found " + img.width() + "x" + img.height() + ", expected " + width + "x" + height);
        }
        return img.rgb();
    }

    /** How {@code a} and {@code b} (packed 0xRRGGBB, same size) differ. */
    static Difference compare(int[] a, int[] b) {
        if (a.length != b.length || a.length == 0) throw new IllegalArgumentException("images of " + a.length + " and " + b.length + " pixels");
        double sum = 0;
        long off = 0;
        for (int i = 0; i < a.length; i++) {
            double d = Math.abs(luma(a[i]) - luma(b[i]));
            sum += d;
            if (d > 0.05 * 255) off++;
        }
        return new Difference(sum / a.length, off / (double) a.length);
    }

    private static double luma(int rgb) {
        return 0.2126 * (rgb >> 16 & 0xFF) + 0.7152 * (rgb >> 8 & 0xFF) + 0.0722 * (rgb & 0xFF);
    }
}
