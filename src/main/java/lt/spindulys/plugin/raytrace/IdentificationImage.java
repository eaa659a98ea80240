package lt.spindulys.plugin.raytrace;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import lt.spindulys.image.AovFrame;
import lt.spindulys.limits.MessageText;
import lt.spindulys.plugin.DisplayedSurface;

/**
 * The per-surface identification picture (the thesis's future work): every pixel of the object
 * render pass coloured by the surface it shows, in a fixed palette of distinct colours, the floor
 * and the background in neutral greys, and below it a legend that names each surface, the
 * subdivision the host applied and how the ray tracer rendered it, drawn with the built-in
 * {@link BitmapFont} so the picture is the same on every machine.
 *
 * @param width  the picture's width
 * @param height the picture's height
 * @param rgb    0xRRGGBB per pixel, rows from the top
 */
record IdentificationImage(int width, int height, int[] rgb) {
    /** Colour of the background (rays that hit nothing). */
    static final int BACKGROUND = 0x303030;
    /** Colour of the floor. */
    static final int FLOOR = 0x9A9A9A;
    /** Colour of the legend's panel and its text. */
    static final int PANEL = 0xF4F4F4, TEXT = 0x000000;

    /** Distinct colours for the first surfaces (Tableau's ten without its grey, which the floor uses). */
    private static final int[] PALETTE = {0x4E79A7, 0xF28E2B, 0xE15759, 0x76B7B2, 0x59A14F, 0xEDC948, 0xB07AA1, 0xFF9DA7, 0x9C755F};

    /**
     * The colour of surface {@code i}: the palette, then hues a golden angle apart; never a
     * neutral colour and never one an earlier surface has.
     */
    static int colour(int i) {
        return palette(i + 1)[i];
    }

    private static int[] palette(int n) {
        Set<Integer> used = new LinkedHashSet<>();
        used.add(BACKGROUND);
        used.add(FLOOR);
        used.add(PANEL);
        used.add(TEXT);
        int[] out = new int[n];
        for (int i = 0; i < n; i++) {
            int c;
            if (i < PALETTE.length) {
                c = PALETTE[i];
            } else {
                int k = i - PALETTE.length;
                float hue = (float) ((k * 0.6180339887498949) % 1.0);
                c = java.awt.Color.HSBtoRGB(hue, k % 2 == 0 ? 0.75f : 0.5f, (k / 2) % 2 == 0 ? 0.9f : 0.7f) & 0xFFFFFF;
            }
            while (used.contains(c)) c = (c + 0x010305) & 0xFFFFFF; // a step away from a colour already taken
            used.add(c);
            out[i] = c;
        }
        return out;
    }

    /**
     * Makes the picture.
     *
     * @param passes   the render's passes, with the object pass (surface i is object i, the floor object n)
     * @param surfaces the surfaces as the host gave them
     * @param rendered how each was rendered, in the same order
     * @return the picture
     */
    static IdentificationImage of(AovFrame passes, List<DisplayedSurface> surfaces, List<String> rendered) {
        int n = surfaces.size(), w = passes.width(), h = passes.height();
        int[] colours = palette(n);
        long[] pixels = new long[n];
        List<String> lines = new ArrayList<>();
        int[] region = new int[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int id = passes.objectId(x, y);
                int c;
                if (id >= 0 && id < n) {
                    c = colours[id];
                    pixels[id]++;
                } else {
                    c = id < 0 ? BACKGROUND : FLOOR;
                }
                region[y * w + x] = c;
            }
        }
        // Two lines a surface: what it is in the viewer, then how it was rendered.
        for (int i = 0; i < n; i++) {
            DisplayedSurface s = surfaces.get(i);
            lines.add(MessageText.cut(SceneDescription.oneLine(s.name())) + ": " + s.subdivisionLabel() + (pixels[i] == 0 ? " (not visible)" : ""));
            lines.add("rendered as " + rendered.get(i));
        }
        // Larger text under larger pictures, where it fits; the panel widens only for text too long at the smallest size.
        int textWidth = 0;
        for (String l : lines) textWidth = Math.max(textWidth, BitmapFont.width(l, 1));
        int scale = w >= 480 && legendWidth(textWidth * 2, 2) <= w ? 2 : 1;
        int pad = 4 * scale, swatch = BitmapFont.GLYPH_HEIGHT * scale, line = BitmapFont.LINE_HEIGHT * scale, entry = 2 * line + 2 * scale;
        int width = Math.max(w, legendWidth(textWidth * scale, scale));
        int height = h + pad + n * entry + pad;
        int[] rgb = new int[width * height];
        java.util.Arrays.fill(rgb, PANEL);
        for (int y = 0; y < h; y++) System.arraycopy(region, y * w, rgb, y * width, w);
        for (int i = 0; i < n; i++) {
            int top = h + pad + i * entry;
            for (int y = 0; y < swatch; y++) {
                for (int x = 0; x < swatch; x++) rgb[(top + y) * width + pad + x] = colours[i];
            }
            BitmapFont.draw(rgb, width, pad + swatch + pad, top, lines.get(2 * i), TEXT, scale);
            BitmapFont.draw(rgb, width, pad + swatch + pad, top + line, lines.get(2 * i + 1), TEXT, scale);
        }
        return new IdentificationImage(width, height, rgb);
    }

    /** The legend's width for text this wide: padding, swatch, padding, text, padding. */
    private static int legendWidth(int text, int scale) {
        return 4 * scale + BitmapFont.GLYPH_HEIGHT * scale + 4 * scale + text + 4 * scale;
    }
}
