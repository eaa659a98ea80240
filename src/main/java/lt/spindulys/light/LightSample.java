package lt.spindulys.light;

import lt.spindulys.scene.EnvironmentLight;

/**
 * One sample of a light seen from a shaded point, filled by {@link Light#sampleLi}: where the
 * light is, what arrives from it, and with what density the direction was drawn. Mutable and
 * reused: one per thread, overwritten by every sample, so drawing a sample allocates nothing.
 */
public final class LightSample {
    /** Unit direction from the shaded point towards the sample. */
    public double wx, wy, wz;
    /** Distance from the shaded point to the sample, positive; +Infinity for the environment. */
    public double distance;
    /** The sampled point (a point light's position); unused when {@link #distance} is infinite. */
    public double x, y, z;
    /**
     * Where a shadow ray from near the shaded point towards (x, y, z) stops, in its parameter
     * (t = 1 at the sample): 1 for a point light, just short of it for a point on a surface, so
     * that geometry the light lies on (a disc on a ceiling) does not block it.
     */
    public double shadowTMax;
    /**
     * Radiance arriving along w from the sample, before anything in between: an area light's or
     * the environment's radiance, or for a point light (a delta) its colour times intensity over
     * the falloff at this distance.
     */
    public double r, g, b;
    /** The density in solid angle with which w was drawn; 1 for a point light. */
    public double pdf;
    /** Whether the light is a point: no direction drawn otherwise reaches it (so MIS weighs it 1). */
    public boolean delta;
    /**
     * This sample's share of the light's estimate at the point: radiance / (pdf * the light's
     * samples), what the Whitted integrator reflects before the receiver's cosine and the shadow
     * ray's transmission. Computed by the light in the order its images were always computed, so
     * they stay the same to the last bit.
     */
    public double weightedR, weightedG, weightedB;

    /** What {@link EnvironmentLight#sample} writes, read at once by {@link EnvironmentSource}. */
    final double[] drawn = new double[7];
}
