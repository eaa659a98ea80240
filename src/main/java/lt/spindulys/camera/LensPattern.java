package lt.spindulys.camera;

import java.util.ArrayList;
import java.util.List;

/**
 * Where a pixel's lens samples lie on the unit disk (the camera scales them by its aperture). The
 * renderer's pixel sampler places them; a pinhole camera ignores them.
 */
public enum LensPattern {
    /**
     * The default: the pixel's stratified square samples mapped onto the disk by Shirley and
     * Chiu's concentric map, which keeps the strata equal in area and compact, so the lens is
     * covered evenly.
     */
    CONCENTRIC("concentric"),
    /**
     * The thesis's pattern, for comparison: for n samples, sample k lies at angle 2πk/n, at radius
     * 1 for even k and 1/2 for odd k. With one sample it is the lens centre (one camera on the rim
     * would only shift the view). Not random: out-of-focus points become rings of n sharp copies.
     */
    RING("ring");

    private final String keyword;

    LensPattern(String keyword) { this.keyword = keyword; }

    /**
     * The word that names the pattern in scene files.
     *
     * @return the keyword
     */
    public String keyword() { return keyword; }

    /**
     * The pattern named {@code word}.
     *
     * @param word the keyword
     * @return the pattern
     * @throws IllegalArgumentException if no pattern has that keyword
     */
    public static LensPattern fromKeyword(String word) {
        for (LensPattern p : values()) if (p.keyword.equals(word)) return p;
        throw new IllegalArgumentException("unknown lens pattern '" + word + "', expected " + String.join(" or ", keywords()));
    }

    /**
     * Every pattern's keyword, in declaration order.
     *
     * @return the keywords
     */
    public static List<String> keywords() {
        List<String> out = new ArrayList<>();
        for (LensPattern p : values()) out.add(p.keyword);
        return List.copyOf(out);
    }
}
