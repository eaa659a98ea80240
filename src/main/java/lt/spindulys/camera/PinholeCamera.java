package lt.spindulys.camera;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/**
 * A pinhole camera: eye, look-at point, up vector and vertical field of view in degrees. Every ray
 * starts at the eye, so everything is sharp; the lens sample is ignored. {@link ThinLensCamera}
 * adds a lens to this view.
 */
public final class PinholeCamera implements Camera {
    private final Vec3 eye, lookAt, up;
    private final double fovDegrees;
    // Orthonormal frame: right, true up, forward; tanHalf scales the film plane at distance 1.
    // Package-private: a ThinLensCamera places its lens in this frame.
    final double rx, ry, rz, ux, uy, uz, fx, fy, fz, tanHalf;

    /**
     * A camera at {@code eye} looking at {@code lookAt}.
     *
     * @param eye where the camera is
     * @param lookAt the point at the centre of the image
     * @param up which way is up (need not be perpendicular to the view; not parallel to it)
     * @param fovDegrees the vertical field of view in degrees, between 0 and 180
     * @throws IllegalArgumentException if a vector is not finite, the view is degenerate or the angle out of range
     */
    public PinholeCamera(Vec3 eye, Vec3 lookAt, Vec3 up, double fovDegrees) {
        if (!(fovDegrees > 0 && fovDegrees < 180)) throw new IllegalArgumentException("fov must be between 0 and 180 degrees, found " + fovDegrees);
        ViewBasis basis = ViewBasis.of(eye, lookAt, up);
        Vec3 r = basis.right(), u = basis.up(), f = basis.forward();
        this.eye = eye; this.lookAt = lookAt; this.up = up; this.fovDegrees = fovDegrees;
        rx = r.x(); ry = r.y(); rz = r.z();
        ux = u.x(); uy = u.y(); uz = u.z();
        fx = f.x(); fy = f.y(); fz = f.z();
        tanHalf = Math.tan(Math.toRadians(fovDegrees) / 2);
    }

    /** {@return where the camera is} */
    public Vec3 eye() { return eye; }
    /** {@return the point at the centre of the image} */
    public Vec3 lookAt() { return lookAt; }
    /** {@return the up direction as given} */
    public Vec3 up() { return up; }
    /** {@return the vertical field of view, degrees} */
    public double fovDegrees() { return fovDegrees; }

    /** {@inheritDoc} The pinhole becomes a thin lens, focused on its look-at point unless {@code focus} says otherwise. */
    @Override
    public ThinLensCamera withLens(Double aperture, Double focus) {
        return new ThinLensCamera(this, 0).withLens(aperture, focus);
    }

    @Override
    public void generateRay(double filmX, double filmY, double aspect, double lensU, double lensV, double time, Ray out) {
        double sx = (2 * filmX - 1) * tanHalf * aspect;
        double sy = (1 - 2 * filmY) * tanHalf;
        double dx = fx + sx * rx + sy * ux, dy = fy + sx * ry + sy * uy, dz = fz + sx * rz + sy * uz;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        out.set(eye.x(), eye.y(), eye.z(), dx * inv, dy * inv, dz * inv, 0, Double.POSITIVE_INFINITY);
        out.time = time;
    }
}
