package lt.spindulys.scene;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.sampling.Distribution2D;
import lt.spindulys.texture.TextureImage;

/**
 * An {@link Environment} as a light: directions drawn in proportion to the map's brightness, so
 * that shadow rays go where the sky's light comes from (a sun of a few texels gets most of them).
 * Built once, when a scene whose environment {@link Environment#isLight() is a light} is frozen.
 *
 * <p>Each texel's cell of the lat-long map (a band of directions 1/w of a turn wide and 1/h of
 * the polar angle high) gets the weight luminance x the cell's solid angle, the luminance being
 * the mean over the cell of what {@link Environment#lookup} returns there (a 3 x 3 blend of the
 * texel and its neighbours, weights 1/8, 3/4, 1/8 across and down: the bilinear lookup reaches
 * the neighbours, so every cell that can show light has a weight). The solid angle of row j is
 * 2pi/w (cos(pi j/h) - cos(pi (j+1)/h)), the exact integral of sin(theta) over the band. A drawn
 * cell's direction is uniform in solid angle within it (uniform in azimuth and in cos(theta)),
 * so the density in solid angle is constant over a cell: P(cell) / solid angle(cell), finite at
 * the poles.
 *
 * <p>Radiance is the environment's own (map x intensity, what camera rays see), so the estimate
 * radiance x cos / pdf, averaged, is the irradiance, in the units of an area light's: a white
 * map of value L lights an open, upward-facing point with pi L. Immutable and thread-safe.
 */
public final class EnvironmentLight {
    /** Rec. 709 luminance weights: the distribution follows perceived brightness; all positive, so any lit channel counts. */
    private static final double LR = 0.2126, LG = 0.7152, LB = 0.0722;

    private final Environment environment;
    private final Distribution2D distribution;
    private final int w, h;
    /** cos(theta) at the top of each row: zTop[j] = cos(pi j / h), h + 1 values. */
    private final double[] zTop;
    /** The solid angle of one cell of each row. */
    private final double[] cellSolidAngle;
    /** The rotation as a fraction of a turn (the environment's). */
    private final double uShift;

    private EnvironmentLight(Environment environment) {
        this.environment = environment;
        TextureImage map = environment.map();
        w = map.width();
        h = map.height();
        zTop = new double[h + 1];
        cellSolidAngle = new double[h];
        for (int j = 0; j <= h; j++) zTop[j] = Math.cos(Math.PI * j / h);
        zTop[0] = 1;
        zTop[h] = -1;
        for (int j = 0; j < h; j++) {
            // cos a - cos b = 2 sin((a+b)/2) sin((b-a)/2), without cancellation near the poles.
            cellSolidAngle[j] = 2 * Math.PI / w * 2 * Math.sin(Math.PI * (2 * j + 1) / (2.0 * h)) * Math.sin(Math.PI / (2.0 * h));
        }
        uShift = environment.uShift();
        double[] above = new double[w], here = new double[w], below = new double[w], column = new double[w];
        distribution = new Distribution2D(w, h, (j, into) -> {
            luminance(map, Math.max(0, j - 1), above);
            luminance(map, j, here);
            luminance(map, Math.min(h - 1, j + 1), below);
            for (int i = 0; i < w; i++) column[i] = 0.125 * above[i] + 0.75 * here[i] + 0.125 * below[i];
            for (int i = 0; i < w; i++) {
                double left = column[i == 0 ? w - 1 : i - 1], right = column[i + 1 == w ? 0 : i + 1];
                into[i] = (0.125 * left + 0.75 * column[i] + 0.125 * right) * cellSolidAngle[j];
            }
        });
    }

    private static void luminance(TextureImage map, int row, double[] out) {
        for (int i = 0; i < out.length; i++) {
            double l = LR * map.texel(0, i, row, 0) + LG * map.texel(0, i, row, 1) + LB * map.texel(0, i, row, 2);
            out[i] = Math.max(0, l);
        }
    }

    /**
     * The light of {@code environment}, its tables checked against the heap first.
     *
     * @param environment the environment (its {@link Environment#isLight()} is not consulted)
     * @return the light
     * @throws lt.spindulys.limits.InsufficientMemoryException if the tables do not fit
     */
    public static EnvironmentLight of(Environment environment) {
        requireTables(environment.map());
        return new EnvironmentLight(environment);
    }

    /**
     * Checks that the sampling tables of a light over {@code map} fit in the heap now. The scene
     * reader calls it where the statement makes the environment a light, so that a map too large
     * is reported there; {@link #of} checks again when the scene is built and the tables are made.
     *
     * @param map the environment's image
     * @throws lt.spindulys.limits.InsufficientMemoryException if they do not fit
     */
    public static void requireTables(TextureImage map) {
        int w = map.width(), h = map.height();
        long bytes = HeapBudget.sum(Distribution2D.bytes(w, h), HeapBudget.product(8, HeapBudget.sum(2L * h + 1, 5L * w)));
        HeapBudget.require(bytes, "the environment light's sampling tables for the " + w + "x" + h + " map");
    }

    /** The environment. @return it */
    public Environment environment() { return environment; }

    /**
     * Whether the map is black (or the intensity 0): nothing to sample, no light.
     *
     * @return true if there is no light
     */
    public boolean isBlack() { return distribution.total() == 0 || environment.intensity() == 0; }

    /**
     * A direction for the uniform pair (u1, u2) in [0, 1)^2 (u1 draws the polar band, u2 the
     * azimuth within it): writes the unit direction to out[0..2], 1 / pdf (the solid angle this
     * sample stands for, in steradians) to out[3], and the radiance seen along it to out[4..6].
     * Must not be called when {@link #isBlack()}.
     *
     * @param u1  uniform number
     * @param u2  uniform number
     * @param out at least 7 values
     */
    public void sample(double u1, double u2, double[] out) {
        double one = Math.nextDown(1.0);
        distribution.sample(Math.min(Math.max(u1, 0), one), Math.min(Math.max(u2, 0), one), out);
        int i = (int) out[0], j = (int) out[1];
        double tu = out[2], tv = out[3];
        double u = (i + tu) / w; // image u, in [0, 1)
        double z = zTop[j] - tv * (zTop[j] - zTop[j + 1]);
        double sin = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = 2 * Math.PI * (u - uShift);
        // The inverse of the lookup's u = atan2(dx, -dz) / 2pi + shift.
        double dx = sin * Math.sin(phi), dz = -sin * Math.cos(phi);
        double solidAngle = cellSolidAngle[j] / distribution.probability(i, j);
        double v = Environment.atan2(sin, z) / Math.PI;
        environment.lookupImage(u, v, out, 4);
        out[0] = dx;
        out[1] = z;
        out[2] = dz;
        out[3] = solidAngle;
    }

    /**
     * The density in solid angle with which {@link #sample} draws the UNIT direction d.
     *
     * @param dx direction x
     * @param dy direction y
     * @param dz direction z
     * @return the pdf, per steradian; 0 when {@link #isBlack()}
     */
    public double pdf(double dx, double dy, double dz) {
        if (distribution.total() == 0) return 0;
        double u = Environment.atan2(dx, -dz) * (0.5 / Math.PI) + uShift;
        u -= Math.floor(u);
        double theta = Environment.atan2(Math.sqrt(dx * dx + dz * dz), dy);
        int i = Math.min(w - 1, (int) (u * w));
        int j = Math.min(h - 1, (int) (theta / Math.PI * h));
        return distribution.probability(i, j) / cellSolidAngle[j];
    }
}
