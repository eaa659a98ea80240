package lt.spindulys.math;

/** Immutable linear RGB colour, for materials, lights and settings. Components may exceed 1. */
public record Color(double r, double g, double b) {
    public static final Color BLACK = new Color(0, 0, 0);
    public static final Color WHITE = new Color(1, 1, 1);

    public static Color grey(double v) { return new Color(v, v, v); }

    public boolean isFinite() { return Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b); }
    public boolean isNonNegative() { return r >= 0 && g >= 0 && b >= 0; }
    public boolean isBlack() { return r == 0 && g == 0 && b == 0; }
    public double max() { return Math.max(r, Math.max(g, b)); }
    public Color times(double s) { return new Color(r * s, g * s, b * s); }
    public double get(int channel) { return channel == 0 ? r : channel == 1 ? g : b; }

    @Override public String toString() { return "(" + r + ", " + g + ", " + b + ")"; }
}
