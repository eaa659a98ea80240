package lt.spindulys.viewer;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Vec3;

/**
 * The viewer's camera: it looks at a target from a distance, at a yaw (about the world's y axis)
 * and a pitch (above or below the horizon) that stops short of the poles, so that "up" never
 * degenerates. Mutable and not thread safe: the viewer changes it on the event thread and hands
 * copies ({@link #copy()}) to whoever needs a stable view.
 */
public final class OrbitCamera {
    /** Radians turned per pixel dragged. */
    static final double RADIANS_PER_PIXEL = Math.toRadians(0.5);
    /** The pitch stops this far short of straight up or down. */
    static final double MAX_PITCH = Math.toRadians(89);
    /** Distances closer or farther than these are clamped (float depth stays meaningful). */
    static final double MIN_DISTANCE = 1e-6, MAX_DISTANCE = 1e9;

    private Vec3 target = Vec3.ZERO;
    private double distance = 5, yaw, pitch = Math.toRadians(20), fov = 45;

    /** A camera 5 units from the origin, a little above it, with a 45 degree vertical field of view. */
    public OrbitCamera() {}

    /** {@return an independent copy} */
    public OrbitCamera copy() {
        OrbitCamera c = new OrbitCamera();
        c.target = target;
        c.distance = distance;
        c.yaw = yaw;
        c.pitch = pitch;
        c.fov = fov;
        return c;
    }

    /** {@return the point looked at} */
    public Vec3 target() { return target; }
    /** {@return the distance from the eye to the target} */
    public double distance() { return distance; }
    /** {@return the yaw in radians: 0 looks down -z (the eye on +z)} */
    public double yaw() { return yaw; }
    /** {@return the pitch in radians: positive puts the eye above the target} */
    public double pitch() { return pitch; }
    /** {@return the vertical field of view in degrees} */
    public double fovDegrees() { return fov; }

    /**
     * Sets the vertical field of view.
     *
     * @param degrees between 1 and 170
     * @throws IllegalArgumentException outside that range
     */
    public void fovDegrees(double degrees) {
        if (!(degrees >= 1 && degrees <= 170)) throw new IllegalArgumentException("field of view must be between 1 and 170 degrees, found " + degrees);
        fov = degrees;
    }

    /**
     * Places the camera directly (for tests and for restoring a view).
     *
     * @param target the point looked at
     * @param distance from the eye to the target, clamped to a sane range
     * @param yaw radians about the y axis
     * @param pitch radians, clamped short of the poles
     */
    public void set(Vec3 target, double distance, double yaw, double pitch) {
        this.target = target;
        this.distance = clampDistance(distance);
        this.yaw = yaw;
        this.pitch = clampPitch(pitch);
    }

    /** {@return where the eye is} */
    public Vec3 eye() { return target.plus(backward().times(distance)); }

    /** {@return the unit direction from the eye towards the target} */
    public Vec3 forward() { return backward().times(-1); }

    /** {@return the unit up direction of the image, perpendicular to the view direction} */
    public Vec3 up() {
        double cp = Math.cos(pitch), sp = Math.sin(pitch);
        return new Vec3(-sp * Math.sin(yaw), cp, -sp * Math.cos(yaw));
    }

    /** {@return the unit right direction of the image} */
    public Vec3 right() { return new Vec3(Math.cos(yaw), 0, -Math.sin(yaw)); }

    private Vec3 backward() {
        double cp = Math.cos(pitch);
        return new Vec3(cp * Math.sin(yaw), Math.sin(pitch), cp * Math.cos(yaw));
    }

    /**
     * Turns the eye around the target as if the surface were grabbed and turned with the mouse:
     * dragging right moves the eye left around it, dragging down moves the eye up over it.
     *
     * @param dx pixels dragged to the right
     * @param dy pixels dragged down
     */
    public void orbit(double dx, double dy) {
        // Dragging right turns the object with the mouse: the eye goes the other way round.
        yaw -= dx * RADIANS_PER_PIXEL;
        yaw = Math.IEEEremainder(yaw, 2 * Math.PI);
        pitch = clampPitch(pitch + dy * RADIANS_PER_PIXEL);
    }

    /**
     * Moves eye and target together in the image plane so that the point at the target's depth
     * under the mouse follows it.
     *
     * @param dx pixels dragged to the right
     * @param dy pixels dragged down
     * @param viewportHeight the viewport's height in pixels
     */
    public void pan(double dx, double dy, int viewportHeight) {
        double perPixel = 2 * distance * Math.tan(Math.toRadians(fov) / 2) / Math.max(1, viewportHeight);
        target = target.plus(right().times(-dx * perPixel)).plus(up().times(dy * perPixel));
    }

    /**
     * Moves the eye towards the target (factor above 1) or away from it (below 1).
     *
     * @param factor how many times closer; must be positive
     * @throws IllegalArgumentException if it is not
     */
    public void zoom(double factor) {
        if (!(factor > 0) || Double.isInfinite(factor)) throw new IllegalArgumentException("zoom factor must be positive, found " + factor);
        distance = clampDistance(distance / factor);
    }

    /** The share of the image's half width and half height a fitted box may fill. */
    static final double FIT_FILL = 0.9;

    /**
     * Looks at the centre of {@code bounds} from the current direction, from just far enough that
     * all eight corners of the box (so everything inside it) project into the image, within
     * {@link #FIT_FILL} of its half width and half height. Fitting the box as seen from this
     * direction, rather than its bounding sphere, makes the surface fill the view as a user
     * expects after F; orbiting afterwards may turn a corner out of view, as in other modellers.
     *
     * @param bounds what must be visible; an empty or infinite box leaves the camera as it is
     * @param aspect the viewport's width over its height
     */
    public void fit(Bounds bounds, double aspect) {
        if (bounds.isEmpty() || !bounds.isFinite()) return;
        Vec3 c = new Vec3((bounds.minX() + bounds.maxX()) / 2, (bounds.minY() + bounds.maxY()) / 2, (bounds.minZ() + bounds.maxZ()) / 2);
        double tanV = Math.tan(Math.toRadians(fov) / 2) * FIT_FILL;
        double tanH = Math.tan(Math.toRadians(fov) / 2) * (aspect > 0 && Double.isFinite(aspect) ? aspect : 1) * FIT_FILL;
        Vec3 r = right(), u = up(), f = forward();
        // A corner q (from the centre) at depth d + q.f from the eye projects inside when
        // |q.r| <= tanH (d + q.f) and |q.u| <= tanV (d + q.f): each gives a least distance d.
        double d = 0;
        for (int k = 0; k < 8; k++) {
            Vec3 q = new Vec3((k & 1) == 0 ? bounds.minX() : bounds.maxX(), (k & 2) == 0 ? bounds.minY() : bounds.maxY(),
                    (k & 4) == 0 ? bounds.minZ() : bounds.maxZ()).minus(c);
            double z = q.dot(f);
            d = Math.max(d, Math.max(Math.abs(q.dot(r)) / tanH, Math.abs(q.dot(u)) / tanV) - z);
        }
        // A flat or point-like box still gets a distance (a point: one unit).
        double size = new Vec3(bounds.maxX() - bounds.minX(), bounds.maxY() - bounds.minY(), bounds.maxZ() - bounds.minZ()).length();
        target = c;
        distance = clampDistance(d > 0 ? d : size > 0 ? size : 1);
    }

    private static double clampPitch(double p) { return Math.max(-MAX_PITCH, Math.min(MAX_PITCH, p)); }

    private static double clampDistance(double d) {
        if (!(d > MIN_DISTANCE)) return MIN_DISTANCE;
        return Math.min(d, MAX_DISTANCE);
    }
}
