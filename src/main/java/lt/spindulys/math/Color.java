package lt.spindulys.math;

/** Immutable linear RGB colour, for materials, lights and settings. Components may exceed 1. */
public record Color(double r, double g, double b) {
    /** No light, or a material that passes none. */
    public static final Color BLACK = new Color(0, 0, 0);
    /** Components all 1. */
    public static final Color WHITE = new Color(1, 1, 1);

    /**
     * A grey.
     *
     * @param v all three components
     * @return the colour
     */
    public static Color grey(double v) { return new Color(v, v, v); }

    /** {@return whether every component is finite} */
    public boolean isFinite() { return Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b); }
    /** {@return whether no component is negative} */
    public boolean isNonNegative() { return r >= 0 && g >= 0 && b >= 0; }
    /** {@return whether every component is exactly 0} */
    public boolean isBlack() { return r == 0 && g == 0 && b == 0; }
    /** {@return the largest component} */
    public double max() { return Math.max(r, Math.max(g, b)); }
    /**
     * The colour scaled.
     *
     * @param s the factor
     * @return each component times {@code s}
     */
    public Color times(double s) { return new Color(r * s, g * s, b * s); }
    /**
     * One component by index.
     *
     * @param channel 0 red, 1 green, 2 blue
     * @return the component
     */
    public double get(int channel) { return channel == 0 ? r : channel == 1 ? g : b; }

    @Override public String toString() { return "(" + r + ", " + g + ", " + b + ")"; }
}
