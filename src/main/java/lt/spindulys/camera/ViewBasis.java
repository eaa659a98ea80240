package lt.spindulys.camera;

import lt.spindulys.math.Ranges;
import lt.spindulys.math.Vec3;

/**
 * The orthonormal frame of a camera looking from an eye at a point: right, up and forward unit
 * vectors, checked once for the cameras that share it (a pinhole, an orthographic view).
 *
 * @param right   unit vector to the image's right (forward x up)
 * @param up      unit vector to the image's top
 * @param forward unit vector from the eye towards the look-at point
 */
record ViewBasis(Vec3 right, Vec3 up, Vec3 forward) {
    /**
     * The frame of a view, with the messages every camera gives for a degenerate one.
     *
     * @throws IllegalArgumentException if a vector is not finite and modest, the eye is the
     *         look-at point, or up is zero or parallel to the view direction
     */
    static ViewBasis of(Vec3 eye, Vec3 lookAt, Vec3 up) {
        if (!Ranges.isModest(eye) || !Ranges.isModest(lookAt) || !Ranges.isModest(up)) throw new IllegalArgumentException("camera vectors must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude");
        Vec3 forward = lookAt.minus(eye);
        if (!(forward.length() > 0)) throw new IllegalArgumentException("camera eye and lookat are the same point " + eye);
        if (!(up.length() > 0)) throw new IllegalArgumentException("camera up vector has zero length");
        Vec3 f = forward.normalized();
        Vec3 r = f.cross(up);
        if (!(r.length() > 1e-12 * up.length())) throw new IllegalArgumentException("camera up vector " + up + " is parallel to the view direction");
        r = r.normalized();
        return new ViewBasis(r, r.cross(f), f);
    }
}
