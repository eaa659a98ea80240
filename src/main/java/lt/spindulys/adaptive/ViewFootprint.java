package lt.spindulys.adaptive;

import java.util.Objects;

import lt.spindulys.camera.Camera;
import lt.spindulys.math.Ray;

/**
 * What the camera sees, for choosing subdivision levels: the eye, the size of a pixel as an angle,
 * and the view frustum. Immutable.
 *
 * <p>Everything is measured through {@link Camera#generateRay} with the lens sample at the lens
 * centre, so any camera works: a thin lens's centre rays are its pinhole's, and the level of
 * detail follows what the film records, not the blur.
 *
 * <p><b>Why the pixel size depends on the direction.</b> On a flat film a small angle seen at
 * angle θ from the view axis covers up to 1 / cos²θ times as many pixels as at the centre (the
 * film is farther away there and met obliquely): about 2x in the corners of a 60° view. A single
 * centre value would be too small off-axis, so {@link #pixels} scales it by 1 / cos²θ of the
 * visible part's outermost direction, and a measured slack (at least 1) covers a camera whose film
 * stretches more than a flat one's.
 */
public final class ViewFootprint {
    private final double ex, ey, ez;          // the eye
    private final double ax, ay, az;          // unit view axis: the lens-centre ray through the image centre
    private final double centrePixelsPerRadian;
    private final double slack;               // >= 1: measured stretch over the 1 / cos² model, off-axis
    private final double minCos;              // cos of the largest angle from the axis inside the frustum
    private final double[] planes;            // 4 unit inward normals of the frustum's sides through the eye
    /** A flat film (a pinhole's, a thin lens's centre rays): its axes in the image plane and pixels per unit of tangent; null otherwise. */
    private double[] film;

    /** Why adaptive subdivision refuses an orthographic camera. */
    public static final String ORTHOGRAPHIC_REFUSAL = "adaptive subdivision sizes edges by their angle at the eye, and an orthographic camera has no eye:"
            + " use method uniform with a level";

    private ViewFootprint(double[] eye, double[] axis, double k0, double slack, double minCos, double[] planes) {
        ex = eye[0]; ey = eye[1]; ez = eye[2];
        ax = axis[0]; ay = axis[1]; az = axis[2];
        this.centrePixelsPerRadian = k0;
        this.slack = slack;
        this.minCos = minCos;
        this.planes = planes;
    }

    /**
     * The footprint of a camera rendering a {@code width} x {@code height} image, derived from
     * the camera's rays only: the eye is the origin of the lens-centre ray through the image
     * centre; the angular pixel size comes from rays one pixel apart at the image centre (the
     * smaller of the two directions' angles, so a pixel of any shape is not underestimated); the
     * frustum from the four corner rays.
     *
     * @param camera the camera
     * @param width image width in pixels, at least 1
     * @param height image height in pixels, at least 1
     * @return the footprint
     * @throws IllegalArgumentException if a size is not positive, the corner rays are not in front of the camera,
     *         or the camera's rays are parallel (orthographic: there is no eye to measure angles at)
     */
    public static ViewFootprint of(Camera camera, int width, int height) {
        Objects.requireNonNull(camera, "camera");
        if (width < 1 || height < 1) throw new IllegalArgumentException("image size must be at least 1x1, found " + width + "x" + height);
        if (camera.pixelFootprint(width, height).width() > 0) throw new IllegalArgumentException(ORTHOGRAPHIC_REFUSAL);
        double aspect = (double) width / height;
        Ray r = new Ray();
        camera.generateRay(0.5, 0.5, aspect, 0, 0, 0, r);
        double[] eye = {r.ox, r.oy, r.oz};
        double[] axis = unit(r.dx, r.dy, r.dz);
        double hx = 0.5 / width, hy = 0.5 / height;
        double k0 = 1 / smallestStretch(camera, aspect, 0.5 - hx, 0.5 + hx, 0.5 - hy, 0.5 + hy, r);
        if (!(k0 > 0 && k0 < Double.POSITIVE_INFINITY)) {
            // Rays one pixel apart that doubles cannot tell apart (a field of view of 1e-300
            // degrees, say): the pixel is narrower than anything measurable, so every edge counts
            // as many pixels long, and gets the finest level allowed (finer is only slower).
            k0 = Double.MAX_VALUE;
        }
        // Corners, edge midpoints and points halfway out: the model 1 / cos² against the
        // measured stretch of a one-pixel step there (towards the centre, so inside the image).
        double slack = 1;
        double[] fs = {0, 0.25, 0.5, 0.75, 1};
        for (double fx : fs) {
            for (double fy : fs) {
                if (fx == 0.5 && fy == 0.5) continue;
                double x1 = fx + (fx < 0.5 ? 2 * hx : -2 * hx), y1 = fy + (fy < 0.5 ? 2 * hy : -2 * hy);
                double fx0 = Math.min(fx, x1), fx1 = Math.max(fx, x1), fy0 = Math.min(fy, y1), fy1 = Math.max(fy, y1);
                double measured = 1 / smallestStretch(camera, aspect, fx0, fx1, fy0, fy1, r);
                // The model's angle: the step's ray nearest the axis, where the model is smallest.
                camera.generateRay(fx < 0.5 ? fx1 : fx0, fy < 0.5 ? fy1 : fy0, aspect, 0, 0, 0, r);
                double[] d = unit(r.dx, r.dy, r.dz);
                double c = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
                if (c > 0 && measured < Double.POSITIVE_INFINITY) slack = Math.max(slack, measured * c * c / k0);
            }
        }
        double[][] corner = new double[4][];
        double[][] film = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        double minCos = 1;
        for (int i = 0; i < 4; i++) {
            camera.generateRay(film[i][0], film[i][1], aspect, 0, 0, 0, r);
            corner[i] = unit(r.dx, r.dy, r.dz);
            minCos = Math.min(minCos, corner[i][0] * axis[0] + corner[i][1] * axis[1] + corner[i][2] * axis[2]);
        }
        if (!(minCos > 0)) throw new IllegalArgumentException("the camera's corner rays are not in front of it (a view of 180 degrees or more)");
        double[] planes = new double[12];
        for (int i = 0; i < 4; i++) {
            double[] p = corner[i], q = corner[(i + 1) % 4];
            double[] n = unit(p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]);
            // Inward: the view axis is on the positive side (corner order may wind either way).
            double s = n[0] * axis[0] + n[1] * axis[1] + n[2] * axis[2] >= 0 ? 1 : -1;
            for (int k = 0; k < 3; k++) planes[3 * i + k] = s * n[k];
        }
        ViewFootprint v = new ViewFootprint(eye, axis, k0, slack, minCos, planes);
        v.film = flatFilm(camera, aspect, width, height, axis, r);
        return v;
    }

    /**
     * The film as a plane at unit distance along the axis, if the camera's lens-centre rays meet
     * one (film positions linear in the image positions, checked at the corners and edge midpoints
     * to a millionth of a pixel): its right and up unit axes and pixels per unit along each, so a
     * point's pixel is its direction's tangent-plane coordinates times those. Null for any other camera.
     */
    private static double[] flatFilm(Camera camera, double aspect, int width, int height, double[] axis, Ray r) {
        double[] x0 = plane(camera, aspect, 0, 0.5, axis, r), x1 = plane(camera, aspect, 1, 0.5, axis, r);
        double[] y0 = plane(camera, aspect, 0.5, 0, axis, r), y1 = plane(camera, aspect, 0.5, 1, axis, r);
        if (x0 == null || x1 == null || y0 == null || y1 == null) return null;
        double[] right = new double[3], up = new double[3];
        for (int k = 0; k < 3; k++) { right[k] = x1[k] - x0[k]; up[k] = y1[k] - y0[k]; }
        double wx = Math.sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
        double wy = Math.sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
        if (!(wx > 0 && wy > 0)) return null;
        for (int k = 0; k < 3; k++) { right[k] /= wx; up[k] /= wy; }
        double sx = width / wx, sy = height / wy;
        // Linear: every corner and midpoint lands where the plane puts it.
        double[] c = plane(camera, aspect, 0.5, 0.5, axis, r);
        for (double fx : new double[] {0, 0.5, 1}) {
            for (double fy : new double[] {0, 0.5, 1}) {
                double[] p = plane(camera, aspect, fx, fy, axis, r);
                if (p == null) return null;
                double px = 0, py = 0;
                for (int k = 0; k < 3; k++) { px += (p[k] - c[k]) * right[k]; py += (p[k] - c[k]) * up[k]; }
                double ex = (fx - 0.5) * width, ey = (fy - 0.5) * height;
                if (Math.abs(px * sx - ex) > 1e-6 * width || Math.abs(py * sy - ey) > 1e-6 * height) return null;
            }
        }
        return new double[] {right[0], right[1], right[2], up[0], up[1], up[2], sx, sy};
    }

    /** Where the lens-centre ray through film point (fx, fy) meets the plane at unit distance along the axis (from the eye); null if it does not. */
    private static double[] plane(Camera camera, double aspect, double fx, double fy, double[] axis, Ray r) {
        camera.generateRay(fx, fy, aspect, 0, 0, 0, r);
        double d = r.dx * axis[0] + r.dy * axis[1] + r.dz * axis[2];
        if (!(d > 0)) return null;
        return new double[] {r.dx / d, r.dy / d, r.dz / d};
    }

    /** The smallest angle (radians) that a one-step film displacement in any direction makes, from two pairs of rays. */
    private static double smallestStretch(Camera camera, double aspect, double x0, double x1, double y0, double y1, Ray r) {
        double fyMid = (y0 + y1) / 2, fxMid = (x0 + x1) / 2;
        camera.generateRay(x0, fyMid, aspect, 0, 0, 0, r);
        double[] a = unit(r.dx, r.dy, r.dz);
        camera.generateRay(x1, fyMid, aspect, 0, 0, 0, r);
        double[] b = unit(r.dx, r.dy, r.dz);
        camera.generateRay(fxMid, y0, aspect, 0, 0, 0, r);
        double[] c = unit(r.dx, r.dy, r.dz);
        camera.generateRay(fxMid, y1, aspect, 0, 0, 0, r);
        double[] d = unit(r.dx, r.dy, r.dz);
        // Chords, not arcs: a chord is never longer than its angle, so the pixel is never overestimated in size.
        double jx0 = b[0] - a[0], jx1 = b[1] - a[1], jx2 = b[2] - a[2];
        double jy0 = d[0] - c[0], jy1 = d[1] - c[1], jy2 = d[2] - c[2];
        // Steps too small to square (a tiny field of view) are scaled up by a power of two first,
        // which changes no bit of the result; steps of ordinary size are left as they are.
        double largest = Math.max(Math.max(Math.max(Math.abs(jx0), Math.abs(jx1)), Math.abs(jx2)),
                Math.max(Math.max(Math.abs(jy0), Math.abs(jy1)), Math.abs(jy2)));
        if (largest > 0 && largest < 0x1p-200) {
            int shift = -Math.getExponent(largest);
            return Math.scalb(chordStretch(Math.scalb(jx0, shift), Math.scalb(jx1, shift), Math.scalb(jx2, shift),
                    Math.scalb(jy0, shift), Math.scalb(jy1, shift), Math.scalb(jy2, shift)), -shift);
        }
        return chordStretch(jx0, jx1, jx2, jy0, jy1, jy2);
    }

    /** The shortest image of a unit film step under the chords jx, jy. */
    private static double chordStretch(double jx0, double jx1, double jx2, double jy0, double jy1, double jy2) {
        // Smallest singular value of the 3x2 matrix [jx jy]: the shortest image of a unit step.
        double p = jx0 * jx0 + jx1 * jx1 + jx2 * jx2, q = jx0 * jy0 + jx1 * jy1 + jx2 * jy2, s = jy0 * jy0 + jy1 * jy1 + jy2 * jy2;
        double half = (p + s) / 2, dev = Math.hypot((p - s) / 2, q);
        // (p s - q²) / (half + dev) is the same eigenvalue as half - dev without its cancellation.
        double small = (p * s - q * q) / (half + dev);
        return Math.sqrt(Math.max(0, small));
    }

    /**
     * (x, y, z) scaled to length 1; a vector too short to square (the cross product of two corner
     * rays of a tiny field of view) is scaled up by a power of two first, and the zero vector
     * stays zero (a frustum side through corner rays that doubles cannot tell apart then clips
     * nothing, which only counts more of the scene as visible).
     */
    private static double[] unit(double x, double y, double z) {
        double m = Math.max(Math.max(Math.abs(x), Math.abs(y)), Math.abs(z));
        if (m == 0) return new double[3];
        if (m < 0x1p-200) {
            int shift = -Math.getExponent(m);
            x = Math.scalb(x, shift);
            y = Math.scalb(y, shift);
            z = Math.scalb(z, shift);
        }
        double l = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / l, y / l, z / l};
    }

    /**
     * Conservative projected length in pixels of the world-space segment a-b: its world length
     * over the distance from the eye to the segment's nearest point, times pixels per radian in
     * the direction of its visible part (foreshortening ignored, so never too small; see the class
     * comment for the direction). Outside the view frustum (or behind the eye) the length is
     * divided by {@code offscreenScale}, as Cycles' offscreen dicing scale does (those parts are
     * seen only in reflections and shadows), with the centre's pixel size: as if the camera
     * turned to face it.
     *
     * @param ax first end, x
     * @param ay first end, y
     * @param az first end, z
     * @param bx second end, x
     * @param by second end, y
     * @param bz second end, z
     * @param offscreenScale divisor outside the view, at least 1 (infinity: offscreen parts count 0 pixels)
     * @return the length in pixels: 0 for a point, infinity for a segment through the eye
     * @throws IllegalArgumentException if {@code offscreenScale} is below 1 or NaN
     */
    public double pixels(double ax, double ay, double az, double bx, double by, double bz, double offscreenScale) {
        checkOffscreenScale(offscreenScale);
        double dx = bx - ax, dy = by - ay, dz = bz - az;
        return pixels(ax, ay, az, bx, by, bz, Math.sqrt(dx * dx + dy * dy + dz * dz), 0, offscreenScale);
    }

    /**
     * The same bound for every segment within {@code pad} of a-b (each end moved at most that far)
     * and at most {@code length} long: the distance is reduced by pad, the frustum widened by pad,
     * and the directions of the visible part turned outwards by the most that pad allows. With pad 0 and the true length it is {@link #pixels(double, double, double, double, double, double, double)}.
     */
    double pixels(double ax, double ay, double az, double bx, double by, double bz, double length, double pad, double offscreenScale) {
        if (length == 0) return 0;
        double dx = bx - ax, dy = by - ay, dz = bz - az;
        double wx = ax - ex, wy = ay - ey, wz = az - ez; // eye to a
        double dd = dx * dx + dy * dy + dz * dz;
        double t = dd > 0 ? Math.max(0, Math.min(1, -(wx * dx + wy * dy + wz * dz) / dd)) : 0;
        double nx = wx + t * dx, ny = wy + t * dy, nz = wz + t * dz;
        double nearest = Math.sqrt(nx * nx + ny * ny + nz * nz), distance = nearest - pad;
        if (!(distance > 0)) return distance <= 0 ? Double.POSITIVE_INFINITY : Double.NaN;
        double angle = length / distance;
        // Clip the segment to the frustum (four half-spaces through the eye, each widened by pad).
        double t0 = 0, t1 = 1;
        for (int i = 0; i < 12 && t0 <= t1; i += 3) {
            double px = planes[i], py = planes[i + 1], pz = planes[i + 2];
            double da = px * wx + py * wy + pz * wz + pad;
            double db = da + px * dx + py * dy + pz * dz;
            if (da < 0 && db < 0) { t0 = 2; break; }
            if (da < 0) t0 = Math.max(t0, da / (da - db));
            else if (db < 0) t1 = Math.min(t1, da / (da - db));
        }
        if (!(t0 <= t1)) return angle * centrePixelsPerRadian / offscreenScale;
        // The visible part's directions form an arc inside the frustum; its angle from the axis is
        // largest at an end of the arc, so the clipped ends bound 1 / cos² over it. A segment
        // within pad of this one, which can be visible only where this one is within pad of the
        // frustum (the widened clip), turns each direction by at most asin(pad / nearest).
        double c = Math.min(cosToAxis(wx + t0 * dx, wy + t0 * dy, wz + t0 * dz), cosToAxis(wx + t1 * dx, wy + t1 * dy, wz + t1 * dz));
        if (pad > 0) {
            // cos(θ + δ) with cos θ = c, sin δ = pad / nearest (< 1 here), without trigonometry;
            // past 90 degrees it is at most 0, below minCos, as wanted.
            double sd = pad / nearest, cc = Math.min(1, c);
            c = cc * Math.sqrt(1 - sd * sd) - Math.sqrt(1 - cc * cc) * sd;
        }
        c = Math.max(minCos, c);
        return angle * centrePixelsPerRadian * slack / (c * c);
    }

    /**
     * The projected length in pixels of the segment a-b by the angle it subtends at the eye (so a
     * segment seen obliquely counts as short as it looks, as Cycles measures its dicing edges in
     * raster space), times pixels per radian in the direction of its visible part with the same
     * 1 / cos² and slack as {@link #pixels(double, double, double, double, double, double, double)},
     * which bounds it from above; outside the view the angle over {@code offscreenScale} with the
     * centre's pixel size.
     *
     * @param ax first end, x
     * @param ay first end, y
     * @param az first end, z
     * @param bx second end, x
     * @param by second end, y
     * @param bz second end, z
     * @param offscreenScale divisor outside the view, at least 1
     * @return the length in pixels: 0 for a point, infinity for a segment through the eye
     */
    public double subtendedPixels(double ax, double ay, double az, double bx, double by, double bz, double offscreenScale) {
        checkOffscreenScale(offscreenScale);
        double dx = bx - ax, dy = by - ay, dz = bz - az;
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (length == 0) return 0;
        double wx = ax - ex, wy = ay - ey, wz = az - ez, vx = bx - ex, vy = by - ey, vz = bz - ez;
        double dd = length * length;
        double t = Math.max(0, Math.min(1, -(wx * dx + wy * dy + wz * dz) / dd));
        double nx = wx + t * dx, ny = wy + t * dy, nz = wz + t * dz;
        if (!(nx * nx + ny * ny + nz * nz > 0)) return Double.POSITIVE_INFINITY;
        double cx = wy * vz - wz * vy, cy = wz * vx - wx * vz, cz = wx * vy - wy * vx;
        double angle = Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), wx * vx + wy * vy + wz * vz);
        double t0 = 0, t1 = 1;
        for (int i = 0; i < 12 && t0 <= t1; i += 3) {
            double px = planes[i], py = planes[i + 1], pz = planes[i + 2];
            double da = px * wx + py * wy + pz * wz;
            double db = da + px * dx + py * dy + pz * dz;
            if (da < 0 && db < 0) { t0 = 2; break; }
            if (da < 0) t0 = Math.max(t0, da / (da - db));
            else if (db < 0) t1 = Math.min(t1, da / (da - db));
        }
        if (!(t0 <= t1)) return angle * centrePixelsPerRadian / offscreenScale;
        double c = Math.max(minCos, Math.min(cosToAxis(wx + t0 * dx, wy + t0 * dy, wz + t0 * dz), cosToAxis(wx + t1 * dx, wy + t1 * dy, wz + t1 * dz)));
        double bound = angle * centrePixelsPerRadian * slack / (c * c);
        if (film == null || !(t1 > t0)) return bound;
        // A flat film: the visible part's exact length in pixels, spread over the whole edge (its
        // segments are even in the edge's parameter), never above the bound.
        double p0x = wx + t0 * dx, p0y = wy + t0 * dy, p0z = wz + t0 * dz, p1x = wx + t1 * dx, p1y = wy + t1 * dy, p1z = wz + t1 * dz;
        // this.a*: the view axis (the parameters a* are the first end).
        double z0 = p0x * this.ax + p0y * this.ay + p0z * this.az, z1 = p1x * this.ax + p1y * this.ay + p1z * this.az;
        if (!(z0 > 0 && z1 > 0)) return bound;
        double[] f = film;
        double du = (p1x * f[0] + p1y * f[1] + p1z * f[2]) / z1 - (p0x * f[0] + p0y * f[1] + p0z * f[2]) / z0;
        double dv = (p1x * f[3] + p1y * f[4] + p1z * f[5]) / z1 - (p0x * f[3] + p0y * f[4] + p0z * f[5]) / z0;
        double visible = Math.hypot(du * f[6], dv * f[7]) / (t1 - t0);
        return Math.min(bound, visible);
    }

    /** Cosine of the angle between (x, y, z) (from the eye) and the view axis; 1 at the eye itself. */
    private double cosToAxis(double x, double y, double z) {
        double l = Math.sqrt(x * x + y * y + z * z);
        return l > 0 ? (x * ax + y * ay + z * az) / l : 1;
    }

    static void checkOffscreenScale(double offscreenScale) {
        if (!(offscreenScale >= 1)) throw new IllegalArgumentException("offscreen scale must be at least 1, found " + offscreenScale);
    }

    /** {@return the eye: the origin of the lens-centre rays, x, y, z in a new array} */
    public double[] eye() { return new double[] {ex, ey, ez}; }

    /** {@return pixels per radian at the image centre (from rays one pixel apart there)} */
    public double centrePixelsPerRadian() { return centrePixelsPerRadian; }

    @Override public String toString() {
        return "ViewFootprint[eye " + ex + " " + ey + " " + ez + ", axis " + ax + " " + ay + " " + az
                + ", " + centrePixelsPerRadian + " px/rad at the centre, slack " + slack + ", widest cos " + minCos + "]";
    }
}
