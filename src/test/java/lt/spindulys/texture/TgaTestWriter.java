package lt.spindulys.texture;

import java.io.ByteArrayOutputStream;

/** Test-only TGA encoder: every type and origin TgaReader accepts, including run-length encoding. */
final class TgaTestWriter {
    private TgaTestWriter() {}

    /**
     * Encodes {@code rgb} (packed 0xRRGGBB, rows top-down) as a TGA of the given type (2, 3, 10,
     * 11) and depth; {@code topDown} sets descriptor bit 5, {@code rightToLeft} bit 4;
     * {@code id} is written as the image ID field.
     */
    static byte[] encode(int w, int h, int[] rgb, int type, int depth, boolean topDown, boolean rightToLeft, String id) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] idBytes = id.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        out.write(idBytes.length);
        out.write(0);  // no colour map
        out.write(type);
        for (int i = 0; i < 5; i++) out.write(0);  // colour map spec
        le16(out, 0);
        le16(out, 0);  // origin
        le16(out, w);
        le16(out, h);
        out.write(depth);
        out.write((topDown ? 0x20 : 0) | (rightToLeft ? 0x10 : 0) | (depth == 32 ? 8 : 0));
        out.write(idBytes, 0, idBytes.length);

        // Pixels in file order.
        int[] order = new int[w * h];
        for (int r = 0, p = 0; r < h; r++) {
            int y = topDown ? r : h - 1 - r;
            for (int c = 0; c < w; c++) order[p++] = rgb[y * w + (rightToLeft ? w - 1 - c : c)];
        }
        int bpp = depth / 8;
        boolean rle = type == 10 || type == 11;
        if (!rle) {
            for (int v : order) pixel(out, v, bpp);
        } else {
            // Greedy: a run packet for repeats, otherwise a raw packet up to the next repeat;
            // packets freely cross scanlines, as the format allows.
            int p = 0;
            while (p < order.length) {
                int run = 1;
                while (p + run < order.length && run < 128 && order[p + run] == order[p]) run++;
                if (run > 1) {
                    out.write(0x80 | (run - 1));
                    pixel(out, order[p], bpp);
                    p += run;
                } else {
                    int n = 1;
                    while (p + n < order.length && n < 128
                            && !(p + n + 1 < order.length && order[p + n] == order[p + n + 1])) n++;
                    out.write(n - 1);
                    for (int k = 0; k < n; k++) pixel(out, order[p + k], bpp);
                    p += n;
                }
            }
        }
        return out.toByteArray();
    }

    private static void pixel(ByteArrayOutputStream out, int v, int bpp) {
        if (bpp == 1) {
            out.write(v & 0xFF);
            return;
        }
        out.write(v & 0xFF);
        out.write(v >> 8 & 0xFF);
        out.write(v >> 16 & 0xFF);
        if (bpp == 4) out.write(0x7F);  // alpha, ignored by the reader
    }

    private static void le16(ByteArrayOutputStream out, int v) {
        out.write(v & 0xFF);
        out.write(v >> 8 & 0xFF);
    }
}
