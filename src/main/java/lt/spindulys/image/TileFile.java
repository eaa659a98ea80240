package lt.spindulys.image;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.zip.CRC32;
import javax.imageio.ImageIO;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InputFiles;

/**
 * A rendered region of a frame as a file: an 8-bit RGB PNG of the region's size whose placement
 * in the frame is recorded in a PNG {@code tEXt} chunk, keyword {@value #KEYWORD}, text
 * {@code X0,X1,Y0,Y1 of WxH} (the region's half-open pixel bounds and the whole frame's size,
 * followed by {@code , frame N} for a frame of an animation),
 * e.g. {@code 0,200,37,75 of 200x150}. The chunk comes right after the header, so the placement is
 * read without decoding the pixels. Any PNG viewer shows a tile as an ordinary image; the
 * {@code render assemble} command reads the placements, checks that the tiles cover the frame
 * exactly once, and copies their pixels, so that the assembled frame is bit for bit the one a
 * whole render writes.
 */
public final class TileFile {
    /** The keyword of the text chunk that holds the placement. */
    public static final String KEYWORD = "spindulys-region";

    private static final byte[] SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    /** The signature and the header chunk (length, type, 13 bytes, CRC): where the placement goes. */
    private static final int AFTER_HEADER = 8 + 4 + 4 + 13 + 4;
    /** Our chunk's text is short; a longer text chunk with our keyword is not ours. */
    private static final int MAX_TEXT = 200;

    private TileFile() {}

    /**
     * Where a tile belongs: its region of a {@code frameWidth x frameHeight} frame, and the
     * animation's frame number it was rendered for (null for a still), so that tiles of different
     * frames are not put together.
     *
     * @param region      the pixels the tile holds
     * @param frameWidth  the whole frame's width
     * @param frameHeight the whole frame's height
     * @param frame       the animation frame, or null for a still
     */
    public record Placement(PixelRegion region, int frameWidth, int frameHeight, Integer frame) {
        private static final String FORM = "expected 'X0,X1,Y0,Y1 of WxH' or 'X0,X1,Y0,Y1 of WxH, frame N'";

        /**
         * Checks that the region lies inside the frame.
         *
         * @throws IllegalArgumentException if it does not, the frame is empty or its number negative
         */
        public Placement {
            if (frameWidth < 1 || frameHeight < 1) throw new IllegalArgumentException("a frame is at least 1x1, found " + frameWidth + "x" + frameHeight);
            if (frame != null && frame < 0) throw new IllegalArgumentException("a frame number is 0 or more, found " + frame);
            region.checkInside(frameWidth, frameHeight);
        }

        /**
         * A still's placement.
         *
         * @param region      the pixels the tile holds
         * @param frameWidth  the whole frame's width
         * @param frameHeight the whole frame's height
         */
        public Placement(PixelRegion region, int frameWidth, int frameHeight) { this(region, frameWidth, frameHeight, null); }

        /** {@return the chunk's text, e.g. {@code 0,200,37,75 of 200x150} or {@code 0,200,37,75 of 200x150, frame 7}} */
        public String text() { return region + " of " + frameWidth + "x" + frameHeight + (frame == null ? "" : ", frame " + frame); }

        /**
         * Reads {@link #text()}.
         *
         * @param text the chunk's text
         * @return the placement
         * @throws IllegalArgumentException if the text is not of that form or not a placement
         */
        public static Placement parse(String text) {
            int of = text.indexOf(" of ");
            int x = of < 0 ? -1 : text.indexOf('x', of);
            if (of < 0 || x < 0) throw new IllegalArgumentException(FORM + ", found '" + text + "'");
            PixelRegion r = PixelRegion.parse(text.substring(0, of));
            int comma = text.indexOf(", frame ", x);
            String height = comma < 0 ? text.substring(x + 1) : text.substring(x + 1, comma);
            try {
                Integer frame = comma < 0 ? null : Integer.valueOf(text.substring(comma + ", frame ".length()));
                return new Placement(r, Integer.parseInt(text.substring(of + 4, x)), Integer.parseInt(height), frame);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(FORM + ", found '" + text + "'");
            }
        }
    }

    /**
     * What writes {@code region} (the rendered region's pixels, of the region's size) as a tile
     * PNG: 8-bit, sRGB-encoded as {@code opts} says, exactly the pixels a whole frame's PNG holds
     * there, and the placement chunk.
     *
     * @param region    the region's pixels
     * @param opts      the encoding options (the sRGB curve)
     * @param placement where the region belongs; its size must be the buffer's
     * @return the body that encodes the tile into a stream
     * @throws IllegalArgumentException if the sizes differ
     * @throws NonFinitePixelException  if a pixel is NaN or infinite as a float
     */
    public static ImageWriter.IoConsumer<OutputStream> encoder(FrameBuffer region, ImageOptions opts, Placement placement) {
        if (region.width() != placement.region().width() || region.height() != placement.region().height()) {
            throw new IllegalArgumentException("a " + region.width() + "x" + region.height() + " image cannot hold the region " + placement.region());
        }
        ImageWriter.checkFinite(region.width(), region.data(), 3);
        ImageWriter.IoConsumer<OutputStream> png = ImageWriter.pngEncoder(region.width(), region.height(), region.toRgb8(opts.srgb()));
        return os -> {
            ByteArrayOutputStream plain = new ByteArrayOutputStream();
            png.accept(plain);
            byte[] b = plain.toByteArray();
            os.write(b, 0, AFTER_HEADER);
            os.write(textChunk(KEYWORD, placement.text()));
            os.write(b, AFTER_HEADER, b.length - AFTER_HEADER);
        };
    }

    /** A PNG tEXt chunk: length, type, keyword, NUL, text, CRC of type and data. */
    static byte[] textChunk(String keyword, String text) {
        byte[] data = (keyword + "\0" + text).getBytes(StandardCharsets.ISO_8859_1);
        byte[] chunk = new byte[12 + data.length];
        putInt(chunk, 0, data.length);
        System.arraycopy("tEXt".getBytes(StandardCharsets.US_ASCII), 0, chunk, 4, 4);
        System.arraycopy(data, 0, chunk, 8, data.length);
        CRC32 crc = new CRC32();
        crc.update(chunk, 4, 4 + data.length);
        putInt(chunk, 8 + data.length, (int) crc.getValue());
        return chunk;
    }

    private static void putInt(byte[] b, int at, int v) {
        b[at] = (byte) (v >>> 24);
        b[at + 1] = (byte) (v >>> 16);
        b[at + 2] = (byte) (v >>> 8);
        b[at + 3] = (byte) v;
    }

    /**
     * The placement of a tile file, read from its chunks before the pixels (which are not decoded),
     * checked against the image's own size.
     *
     * @param file a tile PNG
     * @return its placement
     * @throws IOException if the file cannot be read (the message names it)
     * @throws IllegalArgumentException if it is not a PNG, has no placement, or its size is not its region's (the message names the file)
     */
    public static Placement readPlacement(Path file) throws IOException {
        String problem = InputFiles.problem(file);
        if (problem != null) throw new IllegalArgumentException(file + ": tile " + problem);
        try (InputStream raw = InputFiles.open(file); DataInputStream in = new DataInputStream(new java.io.BufferedInputStream(raw))) {
            byte[] sig = new byte[8];
            in.readFully(sig);
            if (!Arrays.equals(sig, SIGNATURE)) throw new IllegalArgumentException(file + ": not a PNG file (a tile is a PNG written by render --region or --tile)");
            int width = -1, height = -1;
            Placement found = null;
            while (true) {
                int length = in.readInt();
                byte[] typeBytes = new byte[4];
                in.readFully(typeBytes);
                String type = new String(typeBytes, StandardCharsets.ISO_8859_1);
                if (length < 0) throw new IllegalArgumentException(file + ": damaged PNG (chunk " + type + " has a negative length)");
                if (type.equals("IHDR") && length == 13) {
                    width = in.readInt();
                    height = in.readInt();
                    skip(in, 5 + 4);
                } else if (type.equals("tEXt") && length <= MAX_TEXT) {
                    byte[] data = new byte[length];
                    in.readFully(data);
                    skip(in, 4);
                    String s = new String(data, StandardCharsets.ISO_8859_1);
                    if (s.startsWith(KEYWORD + "\0")) {
                        try {
                            found = Placement.parse(s.substring(KEYWORD.length() + 1));
                        } catch (IllegalArgumentException e) {
                            throw new IllegalArgumentException(file + ": bad " + KEYWORD + " chunk: " + e.getMessage());
                        }
                    }
                } else if (type.equals("IDAT") || type.equals("IEND")) {
                    break;
                } else {
                    skip(in, (long) length + 4);
                }
            }
            if (found == null) {
                throw new IllegalArgumentException(file + ": not a tile (no " + KEYWORD + " text chunk saying where it belongs; tiles are written by render --region or --tile)");
            }
            if (width != found.region().width() || height != found.region().height()) {
                throw new IllegalArgumentException(file + ": the image is " + width + "x" + height + " but its region " + found.region() + " is "
                        + found.region().width() + "x" + found.region().height());
            }
            return found;
        } catch (EOFException e) {
            throw new IllegalArgumentException(file + ": damaged PNG (the file ends before its first image data)");
        }
    }

    private static void skip(DataInputStream in, long n) throws IOException {
        while (n > 0) {
            long s = in.skip(n);
            if (s <= 0) {
                if (in.read() < 0) throw new EOFException();
                s = 1;
            }
            n -= s;
        }
    }

    /**
     * The pixels of a tile whose placement {@link #readPlacement} read: packed {@code 0xRRGGBB}
     * values, row-major, top row first, the region's size. The heap is checked for the file and
     * the decoded image first.
     *
     * @param file      the tile
     * @param placement its placement
     * @return {@code width * height} pixels of the region
     * @throws IOException if the file cannot be read
     * @throws IllegalArgumentException if it cannot be decoded or its size changed
     */
    public static int[] readPixels(Path file, Placement placement) throws IOException {
        PixelRegion r = placement.region();
        HeapBudget.require(HeapBudget.product(r.width(), r.height(), 4 + 4 + 4), "the " + r.width() + "x" + r.height() + " tile " + file);
        byte[] bytes = InputFiles.readAllBytes(file, "tile", 1);
        BufferedImage img;
        try {
            img = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            throw new IllegalArgumentException(file + ": damaged PNG (" + e.getMessage() + ")");
        }
        if (img == null) throw new IllegalArgumentException(file + ": the PNG could not be decoded");
        if (img.getWidth() != r.width() || img.getHeight() != r.height()) {
            throw new IllegalArgumentException(file + ": the image is " + img.getWidth() + "x" + img.getHeight() + " but its region " + r + " is " + r.width() + "x" + r.height());
        }
        int[] rgb = img.getRGB(0, 0, r.width(), r.height(), null, 0, r.width());
        for (int i = 0; i < rgb.length; i++) rgb[i] &= 0xFFFFFF;
        return rgb;
    }
}
