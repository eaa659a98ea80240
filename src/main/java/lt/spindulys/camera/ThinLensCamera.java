package lt.spindulys.camera;

import java.util.Objects;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/**
 * A thin-lens camera for depth of field: the view (eye, look-at, up, field of view) of a
 * {@link PinholeCamera}, with a round lens of radius {@code aperture} centred on the eye in the
 * image plane, focused on the plane at distance {@code focusDistance} along the view direction.
 *
 * <p>A film point's ray starts at a point of the lens and passes through the point of the focal
 * plane that the pinhole ray through the same film point reaches, so points on the focal plane
 * are as sharp as with the pinhole, and a point at distance d along the view direction is spread
 * over a disk on the film of diameter 2 · aperture · |d − focus| / (d · focus), in the units of
 * the film plane at distance 1 (where the image is 2 · tan(fov/2) high). With aperture 0, or the
 * lens sample at the centre, the ray is exactly the pinhole's.
 */
public final class ThinLensCamera implements Camera {
    private final PinholeCamera view;
    private final double aperture, focusDistance;
    private final LensPattern lens;

    /**
     * @param view          where the camera is and what it sees
     * @param aperture      lens radius in scene units, at least 0 (0: a pinhole)
     * @param focusDistance distance from the eye to the focal plane along the view direction, positive
     * @param lens          how the lens samples are placed on the lens
     */
    public ThinLensCamera(PinholeCamera view, double aperture, double focusDistance, LensPattern lens) {
        this.view = Objects.requireNonNull(view, "view");
        this.lens = Objects.requireNonNull(lens, "lens");
        if (!(aperture >= 0 && aperture < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("camera aperture must be a non-negative number, found " + aperture);
        }
        if (!(focusDistance > 0 && focusDistance < Double.POSITIVE_INFINITY)) {
            throw new IllegalArgumentException("camera focus distance must be a positive number, found " + focusDistance);
        }
        this.aperture = aperture;
        this.focusDistance = focusDistance;
    }

    /**
     * A camera focused on the view's look-at point, with the default lens pattern.
     *
     * @param view where the camera is and what it sees
     * @param aperture lens radius in scene units, at least 0 (0: a pinhole)
     */
    public ThinLensCamera(PinholeCamera view, double aperture) {
        this(view, aperture, lookAtDistance(view), LensPattern.CONCENTRIC);
    }

    /**
     * The distance from the eye to the look-at point: the default focus.
     *
     * @param view the view
     * @return the distance, scene units
     */
    public static double lookAtDistance(PinholeCamera view) {
        return view.lookAt().minus(view.eye()).length();
    }

    /**
     * The focus distance that puts {@code point} on the focal plane: its distance from the eye
     * along the view direction.
     *
     * @param view the view
     * @param point a point in front of the eye
     * @return the distance along the view direction
     * @throws IllegalArgumentException if the point is not in front of the eye
     */
    public static double focusDistanceTo(PinholeCamera view, Vec3 point) {
        if (!point.isFinite()) throw new IllegalArgumentException("camera focus point must be finite, found " + point);
        Vec3 d = point.minus(view.eye());
        double along = d.x() * view.fx + d.y() * view.fy + d.z() * view.fz;
        if (!(along > 0)) {
            throw new IllegalArgumentException("camera focus point must be in front of the camera, found " + point
                    + " at " + along + " along the view direction");
        }
        return along;
    }

    /** {@return where the camera is and what it sees} */
    public PinholeCamera view() { return view; }
    /** {@return the lens radius, scene units} */
    public double aperture() { return aperture; }
    /** {@return the distance to the focal plane along the view direction} */
    public double focusDistance() { return focusDistance; }
    @Override public LensPattern lensPattern() { return lens; }
    @Override public boolean usesLens() { return aperture > 0; }

    /**
     * A copy with another lens radius.
     *
     * @param a lens radius in scene units, at least 0
     * @return the camera
     */
    public ThinLensCamera withAperture(double a) { return new ThinLensCamera(view, a, focusDistance, lens); }
    /**
     * A copy focused elsewhere.
     *
     * @param f the distance to the focal plane, positive
     * @return the camera
     */
    public ThinLensCamera withFocusDistance(double f) { return new ThinLensCamera(view, aperture, f, lens); }

    @Override
    public ThinLensCamera withLens(Double aperture, Double focus) {
        ThinLensCamera lens = this;
        if (aperture != null) lens = lens.withAperture(aperture);
        if (focus != null) lens = lens.withFocusDistance(focus);
        return lens;
    }

    @Override
    public void generateRay(double filmX, double filmY, double aspect, double lensU, double lensV, double time, Ray out) {
        view.generateRay(filmX, filmY, aspect, lensU, lensV, time, out);
        if (aperture == 0 || (lensU == 0 && lensV == 0)) return; // the pinhole ray, bit for bit
        PinholeCamera v = view;
        // The pinhole ray (unit direction d) meets the focal plane at t = focus / (d · forward).
        double t = focusDistance / (out.dx * v.fx + out.dy * v.fy + out.dz * v.fz);
        double px = out.dx * t, py = out.dy * t, pz = out.dz * t; // focal point, relative to the eye
        double su = aperture * lensU, sv = aperture * lensV;
        double ox = su * v.rx + sv * v.ux, oy = su * v.ry + sv * v.uy, oz = su * v.rz + sv * v.uz;
        double dx = px - ox, dy = py - oy, dz = pz - oz;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        // Only origin and direction change: the ray's time stays as the view set it.
        out.set(out.ox + ox, out.oy + oy, out.oz + oz, dx * inv, dy * inv, dz * inv, out.tMin, out.tMax);
    }
}
