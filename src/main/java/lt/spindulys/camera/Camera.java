package lt.spindulys.camera;

import lt.spindulys.math.Ray;

/** Turns a point on the film (and a lens sample and a time) into a primary ray. Immutable. */
public interface Camera {
    /**
     * Writes the world-space ray through film position (fx, fy) into {@code out}.
     *
     * @param out receives the ray (its time set to {@code time})
     * @param fx     0 at the left edge of the image, 1 at the right
     * @param fy     0 at the top edge, 1 at the bottom
     * @param aspect image width / height
     * @param lensU  lens sample: a point (lensU, lensV) on the unit disk, (0, 0) the lens centre;
     *               a camera with a lens scales it by its aperture, a pinhole ignores it
     * @param lensV  lens sample, second coordinate
     * @param time   time in the shutter interval
     */
    void generateRay(double fx, double fy, double aspect, double lensU, double lensV, double time, Ray out);

    /**
     * How the renderer should place this camera's lens samples on the unit disk.
     *
     * @return the pattern
     */
    default LensPattern lensPattern() { return LensPattern.CONCENTRIC; }

    /**
     * False if this camera's rays do not depend on the lens sample (a pinhole, or a lens of
     * aperture 0): the renderer then hands it the lens centre and spares mapping samples onto
     * the disk.
     *
     * @return whether the lens sample moves the ray
     */
    default boolean usesLens() { return false; }

    /**
     * True if this camera's rays depend on their time (a camera carried by keys): the renderer
     * then draws each sample's time even when no object moves.
     *
     * @return whether the camera moves while the shutter is open
     */
    default boolean moves() { return false; }

    /**
     * How wide one pixel's footprint is at a distance along this camera's rays, for sizing
     * texture lookups. The default measures the angle between neighbouring pixels' rays, right
     * for any camera whose rays leave one point; a camera with parallel rays overrides it.
     *
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1
     * @return the footprint model
     */
    default PixelFootprint pixelFootprint(int width, int height) { return PixelFootprint.measuredAngle(this, width, height); }

    /**
     * This camera with another lens (for a lens given on the command line): a pinhole becomes a
     * thin lens focused on its look-at point unless a focus is given, a thin lens keeps what is
     * not given, and a camera carried by keys changes the lens of the camera it carries.
     *
     * @param aperture the lens radius in scene units, at least 0 (0: a pinhole); null keeps the camera's
     * @param focus    the distance to the focal plane along the view, positive; null keeps the camera's
     * @return the camera with that lens
     * @throws IllegalArgumentException if a value is out of its range
     * @throws UnsupportedOperationException if this kind of camera has no lens to change
     * @throws IllegalArgumentException also if the camera cannot have a lens (an orthographic one)
     */
    default Camera withLens(Double aperture, Double focus) {
        throw new UnsupportedOperationException(getClass().getName() + " has no lens to change");
    }
}
