package lt.spindulys.viewer;

import lt.spindulys.camera.AnimatedCamera;
import lt.spindulys.camera.Camera;
import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.math.Vec3;

/**
 * How far the user has turned a scene's camera around its look-at point, and moved it nearer or
 * farther, in the scene preview: a turn about the camera's own up vector (yaw), a change of its
 * elevation above the plane across that vector (pitch), and a factor on its distance (dolly).
 * Applied to the scene's camera it gives the camera to render ({@link #apply}); the look-at point,
 * the up vector, the field of view and the lens stay as the scene gives them. Immutable.
 */
record CameraOrbit(double yaw, double pitch, double dolly) {
    /** The camera as the scene gives it. */
    static final CameraOrbit NONE = new CameraOrbit(0, 0, 1);
    /** Radians turned per pixel dragged, as in the mesh viewer. */
    static final double RADIANS_PER_PIXEL = OrbitCamera.RADIANS_PER_PIXEL;
    /** The elevation stops this far short of the up vector (unless the scene's camera starts beyond). */
    static final double MAX_ELEVATION = Math.toRadians(89);
    /** The distance (or an orthographic view's width) changes by this factor per wheel notch. */
    static final double DOLLY_PER_NOTCH = 1.1;
    /** The dolly stays within these factors of the scene's distance, so the eye stays finite and off the look-at point. */
    static final double MIN_DOLLY = 1e-6, MAX_DOLLY = 1e6;

    /** {@return true if this leaves the scene's camera as it is} */
    boolean isNone() { return yaw == 0 && pitch == 0 && dolly == 1; }

    /**
     * This orbit dragged further: right turns the scene with the mouse (the eye goes left round
     * the look-at point), down raises the eye; the elevation stops short of the up vector.
     *
     * @param dx    pixels dragged to the right
     * @param dy    pixels dragged down
     * @param scene the scene's camera, whose elevation the limit applies to
     * @return the new orbit
     */
    CameraOrbit dragged(double dx, double dy, Camera scene) {
        double e0 = elevation(view(scene));
        double limit = Math.max(MAX_ELEVATION, Math.abs(e0));
        double e = Math.max(-limit, Math.min(limit, e0 + pitch + dy * RADIANS_PER_PIXEL));
        return new CameraOrbit(Math.IEEEremainder(yaw - dx * RADIANS_PER_PIXEL, 2 * Math.PI), e - e0, dolly);
    }

    /**
     * This orbit moved nearer (negative notches, the wheel turned away from the user) or farther.
     *
     * @param notches wheel notches, as {@link java.awt.event.MouseWheelEvent#getPreciseWheelRotation()} gives them
     * @return the new orbit
     */
    CameraOrbit dollied(double notches) {
        double d = dolly * Math.pow(DOLLY_PER_NOTCH, notches);
        return new CameraOrbit(yaw, pitch, Math.max(MIN_DOLLY, Math.min(MAX_DOLLY, d)));
    }

    /**
     * The scene's camera moved by this orbit: the same object when the orbit is {@link #NONE}.
     * A thin lens focused on its look-at point stays focused on it; one focused elsewhere keeps its
     * focus distance. An orthographic view keeps its distance and scales its width by the dolly. An
     * animated camera keeps its keys and has its resting camera moved.
     *
     * @param scene the scene's camera
     * @return the camera to render
     * @throws IllegalArgumentException for a kind of camera the preview cannot move
     */
    Camera apply(Camera scene) {
        if (isNone()) return scene;
        if (scene instanceof AnimatedCamera a) return a.withBase(apply(a.base()));
        if (scene instanceof PinholeCamera p) return new PinholeCamera(eye(p.eye(), p.lookAt(), p.up(), dolly), p.lookAt(), p.up(), p.fovDegrees());
        if (scene instanceof ThinLensCamera t) {
            PinholeCamera v = t.view();
            PinholeCamera moved = new PinholeCamera(eye(v.eye(), v.lookAt(), v.up(), dolly), v.lookAt(), v.up(), v.fovDegrees());
            boolean onLookAt = t.focusDistance() == ThinLensCamera.lookAtDistance(v);
            return new ThinLensCamera(moved, t.aperture(), onLookAt ? ThinLensCamera.lookAtDistance(moved) : t.focusDistance(), t.lensPattern());
        }
        if (scene instanceof OrthographicCamera o) {
            return new OrthographicCamera(eye(o.eye(), o.lookAt(), o.up(), 1), o.lookAt(), o.up(), o.viewWidth() * dolly);
        }
        throw new IllegalArgumentException("the preview cannot move a " + scene.getClass().getSimpleName());
    }

    /** Eye, look-at point and up of a camera, for the elevation. */
    private record View(Vec3 eye, Vec3 lookAt, Vec3 up) {}

    private static View view(Camera c) {
        if (c instanceof AnimatedCamera a) return view(a.base());
        if (c instanceof PinholeCamera p) return new View(p.eye(), p.lookAt(), p.up());
        if (c instanceof ThinLensCamera t) return view(t.view());
        if (c instanceof OrthographicCamera o) return new View(o.eye(), o.lookAt(), o.up());
        throw new IllegalArgumentException("the preview cannot move a " + c.getClass().getSimpleName());
    }

    /** The angle of the eye above the plane across the up vector, seen from the look-at point. */
    private static double elevation(View v) {
        Vec3 back = v.eye().minus(v.lookAt()).normalized();
        return Math.asin(Math.max(-1, Math.min(1, back.dot(v.up().normalized()))));
    }

    /** The eye turned and moved by this orbit, at {@code scale} times its distance. */
    private Vec3 eye(Vec3 eye, Vec3 lookAt, Vec3 up, double scale) {
        Vec3 back = eye.minus(lookAt);
        double distance = back.length();
        Vec3 u = up.normalized();
        // The camera's right (forward x up) and the horizontal direction of the eye (right x up):
        // defined whenever the camera is, as up is not along the view.
        Vec3 right = back.times(-1).cross(u).normalized();
        Vec3 level = right.cross(u).normalized();
        double e = elevation(new View(eye, lookAt, up)) + pitch;
        Vec3 around = level.times(Math.cos(yaw)).plus(right.times(Math.sin(yaw)));
        Vec3 dir = around.times(Math.cos(e)).plus(u.times(Math.sin(e)));
        return lookAt.plus(dir.times(distance * scale));
    }
}
