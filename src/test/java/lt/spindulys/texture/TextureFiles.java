package lt.spindulys.texture;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

/**
 * Generates the small texture images committed under textures/ (used by the regression scenes and
 * the documentation): run {@code main} from the repository root to rewrite them;
 * {@link TextureFilesTest} checks that the committed files are what this produces.
 * <ul>
 * <li>dice.png / dice.tga: the 3 x 2 atlas of scenes/models/cube.tex, one cell per cube face,
 * each a colour of its own with the face's number (1 to 6) as die pips and a white frame;</li>
 * <li>grid.png: a UV test grid, red growing with u, green with v, dark lines every 1/8 and a
 * white marker in the (u, v) = (0, 0) corner cell, so orientation and seams are visible.</li>
 * </ul>
 * Pixels are sRGB-encoded 8-bit values (texture loading decodes them to linear).
 */
public final class TextureFiles {
    private TextureFiles() {}

    public static final int DICE_W = 192, DICE_H = 128;
    public static final int GRID_W = 256, GRID_H = 128;

    /** Cell colours by face (row-major from the atlas's v = 0 row, as cube.tex lays the faces out). */
    private static final int[][] FACE_COLOURS = {
            {200, 60, 50}, {230, 160, 40}, {70, 160, 80}, {50, 110, 200}, {140, 80, 180}, {60, 170, 180}};

    /** Pip positions (in thirds of a cell) for 1 to 6. */
    private static final int[][][] PIPS = {
            {{1, 1}},
            {{0, 0}, {2, 2}},
            {{0, 0}, {1, 1}, {2, 2}},
            {{0, 0}, {2, 0}, {0, 2}, {2, 2}},
            {{0, 0}, {2, 0}, {1, 1}, {0, 2}, {2, 2}},
            {{0, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {2, 2}}};

    /**
     * The dice atlas as 0xRRGGBB, row 0 at the top of the image. The atlas's v = 0 is the image's
     * bottom row (the OBJ/.tex convention), so face 1's cell (u, v in [0, 1/3] x [0, 1/2]) is
     * bottom left.
     */
    public static int[] dice() {
        int cell = DICE_W / 3;
        int[] px = new int[DICE_W * DICE_H];
        for (int y = 0; y < DICE_H; y++) {
            for (int x = 0; x < DICE_W; x++) {
                int row = (DICE_H - 1 - y) / cell; // 0 = bottom (v < 1/2)
                int col = x / cell;
                int face = row * 3 + col;
                int cx = x % cell, cy = cell - 1 - (DICE_H - 1 - y) % cell; // cy from the cell's top
                int[] c = FACE_COLOURS[face];
                int rgb = (c[0] << 16) | (c[1] << 8) | c[2];
                if (cx < 3 || cy < 3 || cx >= cell - 3 || cy >= cell - 3) rgb = 0xffffff;
                for (int[] pip : PIPS[face]) {
                    double px0 = (pip[0] + 0.5) * cell / 3.0, py0 = (pip[1] + 0.5) * cell / 3.0;
                    double dx = cx + 0.5 - px0, dy = cy + 0.5 - py0;
                    if (dx * dx + dy * dy <= 36) rgb = 0xf8f8f0;
                }
                px[y * DICE_W + x] = rgb;
            }
        }
        return px;
    }

    /** The UV grid as 0xRRGGBB, row 0 at the top (v = 1). */
    public static int[] grid() {
        int[] px = new int[GRID_W * GRID_H];
        for (int y = 0; y < GRID_H; y++) {
            for (int x = 0; x < GRID_W; x++) {
                int vy = GRID_H - 1 - y; // from the bottom
                int r = 40 + 200 * x / (GRID_W - 1), g = 40 + 200 * vy / (GRID_H - 1), b = 90;
                int rgb = (r << 16) | (g << 8) | b;
                if (x % (GRID_W / 8) < 2 || vy % (GRID_H / 8) < 2) rgb = 0x202020;
                if (x < GRID_W / 8 && vy < GRID_H / 8 && x % (GRID_W / 8) >= 6 && vy % (GRID_H / 8) >= 6
                        && x % (GRID_W / 8) < GRID_W / 8 - 4 && vy % (GRID_H / 8) < GRID_H / 8 - 4) rgb = 0xffffff;
                px[y * GRID_W + x] = rgb;
            }
        }
        return px;
    }

    static BufferedImage image(int w, int h, int[] px) {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, w, h, px, 0, w);
        return img;
    }

    /** An uncompressed 24-bit TGA, bottom-up (the format's default origin). */
    static byte[] tga(int w, int h, int[] px) {
        byte[] out = new byte[18 + w * h * 3];
        out[2] = 2; // uncompressed true colour
        out[12] = (byte) w; out[13] = (byte) (w >> 8);
        out[14] = (byte) h; out[15] = (byte) (h >> 8);
        out[16] = 24;
        int i = 18;
        for (int y = h - 1; y >= 0; y--) {
            for (int x = 0; x < w; x++) {
                int c = px[y * w + x];
                out[i++] = (byte) c; out[i++] = (byte) (c >> 8); out[i++] = (byte) (c >> 16);
            }
        }
        return out;
    }

    public static void main(String[] args) throws IOException {
        Path dir = Path.of(args.length > 0 ? args[0] : "textures");
        Files.createDirectories(dir);
        ImageIO.write(image(DICE_W, DICE_H, dice()), "png", dir.resolve("dice.png").toFile());
        try (OutputStream o = Files.newOutputStream(dir.resolve("dice.tga"))) {
            o.write(tga(DICE_W, DICE_H, dice()));
        }
        ImageIO.write(image(GRID_W, GRID_H, grid()), "png", dir.resolve("grid.png").toFile());
    }
}
