package lt.spindulys.light;

/**
 * A light as the integrator samples it: it draws a direction towards itself from a shaded point
 * for a point of the unit square ({@link #sampleLi}), and tells the density of any direction
 * ({@link #pdfLi}), the two halves of multiple importance sampling. Immutable and shared by the
 * render threads; the sample goes into the caller's per-thread {@link LightSample}.
 *
 * <p>How many samples a light takes and how their unit-square points are drawn is the
 * integrator's: a delta light (a point) takes one sample and no random numbers; the others take
 * {@link #samples()} per pixel sample from strata shared by the pixel's samples.
 */
public abstract sealed class Light permits PointSource, AreaSource, EnvironmentSource, MeshEmitter {
    private final int samples;
    private final boolean delta;

    Light(int samples, boolean delta) {
        this.samples = samples;
        this.delta = delta;
    }

    /**
     * Shadow rays per pixel sample and shaded point.
     *
     * @return at least 1; 1 for a delta light
     */
    public final int samples() { return samples; }

    /**
     * Whether the light is a point (a delta distribution): its sample does not depend on the
     * unit-square point, and no direction drawn by a surface finds it.
     *
     * @return true for a point light
     */
    public final boolean isDelta() { return delta; }

    /**
     * Draws a sample of the light as seen from (px, py, pz) for the unit-square point (u, v) and
     * writes it to {@code out}: its direction, distance, radiance, density and weighted share.
     * Equal areas of the square give equal probabilities (strata stay strata).
     *
     * @param px  the shaded point x
     * @param py  the shaded point y
     * @param pz  the shaded point z
     * @param u   in [0, 1)
     * @param v   in [0, 1)
     * @param out receives the sample; left partly written when this returns false
     * @return false if the sample brings nothing (a one-sided light's back, a point inside a
     *         sphere light or on a light): skip it
     */
    public abstract boolean sampleLi(double px, double py, double pz, double u, double v, LightSample out);

    /**
     * The density in solid angle with which {@link #sampleLi} from (px, py, pz) draws the unit
     * direction w.
     *
     * @param px the shaded point x
     * @param py the shaded point y
     * @param pz the shaded point z
     * @param wx unit direction x
     * @param wy unit direction y
     * @param wz unit direction z
     * @return the pdf per steradian; 0 where no sample goes, and always 0 for a delta light
     */
    public abstract double pdfLi(double px, double py, double pz, double wx, double wy, double wz);

    /**
     * The scene statement that makes this kind of light, for messages: {@code light},
     * {@code rectlight}, {@code disclight}, {@code spherelight}, {@code environment}, or
     * {@code mesh} for an emissive mesh.
     *
     * @return the statement's keyword
     */
    public abstract String statement();
}
