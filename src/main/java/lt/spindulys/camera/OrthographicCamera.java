package lt.spindulys.camera;

import lt.spindulys.math.Ranges;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/**
 * An orthographic camera: eye, look-at point, up vector and the width of the view in scene units
 * (its height follows from the image's aspect ratio). Every ray runs parallel to the view
 * direction, from its point on the image plane through the eye, so sizes do not shrink with
 * distance. There is no lens: everything is sharp and the lens sample is ignored. Immutable.
 */
public final class OrthographicCamera implements Camera {
    private final Vec3 eye, lookAt, up;
    private final double viewWidth;
    // Orthonormal frame: right, true up, forward.
    private final double rx, ry, rz, ux, uy, uz, fx, fy, fz;

    /**
     * A camera at {@code eye} looking at {@code lookAt}, seeing {@code viewWidth} scene units across.
     *
     * @param eye the centre of the image plane, where the rays start
     * @param lookAt a point the view direction runs towards (at the centre of the image)
     * @param up which way is up (need not be perpendicular to the view; not parallel to it)
     * @param viewWidth the width of the view in scene units, positive
     * @throws IllegalArgumentException if a vector is not finite, the view is degenerate or the width out of range
     */
    public OrthographicCamera(Vec3 eye, Vec3 lookAt, Vec3 up, double viewWidth) {
        if (!(viewWidth > 0 && viewWidth <= Ranges.MAX_NUMBER)) throw new IllegalArgumentException("orthographic width must be positive and at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + viewWidth);
        ViewBasis basis = ViewBasis.of(eye, lookAt, up);
        Vec3 r = basis.right(), u = basis.up(), f = basis.forward();
        this.eye = eye; this.lookAt = lookAt; this.up = up; this.viewWidth = viewWidth;
        rx = r.x(); ry = r.y(); rz = r.z();
        ux = u.x(); uy = u.y(); uz = u.z();
        fx = f.x(); fy = f.y(); fz = f.z();
    }

    /** {@return the centre of the image plane} */
    public Vec3 eye() { return eye; }
    /** {@return the point the view runs towards} */
    public Vec3 lookAt() { return lookAt; }
    /** {@return the up direction as given} */
    public Vec3 up() { return up; }
    /** {@return the width of the view in scene units} */
    public double viewWidth() { return viewWidth; }

    @Override
    public void generateRay(double filmX, double filmY, double aspect, double lensU, double lensV, double time, Ray out) {
        double half = viewWidth / 2;
        double sx = (2 * filmX - 1) * half;
        double sy = (1 - 2 * filmY) * half / aspect;
        out.set(eye.x() + sx * rx + sy * ux, eye.y() + sx * ry + sy * uy, eye.z() + sx * rz + sy * uz, fx, fy, fz, 0, Double.POSITIVE_INFINITY);
        out.time = time;
    }

    /** {@inheritDoc} Parallel rays: the pixel's own width at every distance. */
    @Override
    public PixelFootprint pixelFootprint(int width, int height) {
        return new PixelFootprint(viewWidth / width, 0);
    }

    /** {@inheritDoc} An orthographic camera has no lens to focus: refused. */
    @Override
    public Camera withLens(Double aperture, Double focus) {
        throw new IllegalArgumentException("an orthographic camera has no lens: aperture and focus need a perspective camera");
    }
}
