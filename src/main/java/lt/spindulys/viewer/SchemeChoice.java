package lt.spindulys.viewer;

import lt.spindulys.subdiv.SubdivOptions;

/**
 * What the Surface > Scheme menu offers for the selected surface, apart from Swing so that it is
 * tested without a window: each scheme's label, whether it can be chosen (Loop only for a cage of
 * triangles), and the tooltip that says why not.
 */
final class SchemeChoice {
    private SchemeChoice() {}

    /**
     * The menu item's text.
     *
     * @param s the scheme
     * @return "Catmull-Clark (catmark)", "Loop (triangles only)" or "Bilinear (cage split flat)"
     */
    static String label(SubdivOptions.Scheme s) {
        return switch (s) {
            case CATMARK -> "Catmull-Clark (catmark)";
            case LOOP -> "Loop (triangles only)";
            case BILINEAR -> "Bilinear (cage split flat)";
        };
    }

    /**
     * Whether the scheme can be chosen for the surface.
     *
     * @param surface the selected surface, or null
     * @param s the scheme
     * @return false with no surface, and for Loop when the cage has a face that is not a triangle
     */
    static boolean enabled(ViewedSurface surface, SubdivOptions.Scheme s) {
        return surface != null && (s != SubdivOptions.Scheme.LOOP || surface.nonTriangle() == null);
    }

    /**
     * The menu item's tooltip: why Loop is disabled, else null.
     *
     * @param surface the selected surface, or null
     * @param s the scheme
     * @return "Loop needs a cage of triangles: face 3 has 4 corners", or null
     */
    static String tooltip(ViewedSurface surface, SubdivOptions.Scheme s) {
        if (surface == null || s != SubdivOptions.Scheme.LOOP || surface.nonTriangle() == null) return null;
        return "Loop needs a cage of triangles: " + surface.nonTriangle();
    }
}
