package lt.spindulys.plugin;

import java.util.Objects;

import lt.spindulys.math.Vec3;

/**
 * What the host's viewport shows: a pinhole camera and the viewport's size in pixels. A plugin
 * that makes a picture uses it so the picture matches the viewport.
 *
 * @param eye        the camera position
 * @param target     the point the camera looks at (not equal to {@code eye})
 * @param up         the up direction (not parallel to the view direction)
 * @param fovDegrees the vertical field of view in degrees, between 0 and 180 (exclusive)
 * @param width      the viewport width in pixels, at least 1
 * @param height     the viewport height in pixels, at least 1
 */
public record PluginView(Vec3 eye, Vec3 target, Vec3 up, double fovDegrees, int width, int height) {
    /**
     * Checks the camera and the size.
     *
     * @throws IllegalArgumentException naming the value at fault
     */
    public PluginView {
        Objects.requireNonNull(eye, "eye");
        Objects.requireNonNull(target, "target");
        Objects.requireNonNull(up, "up");
        Vec3 dir = target.minus(eye);
        if (!(dir.length() > 0) || !Double.isFinite(dir.length())) {
            throw new IllegalArgumentException("the view's target must differ from its eye, found both at " + eye);
        }
        if (!(dir.cross(up).length() > 1e-12 * dir.length() * up.length())) {
            throw new IllegalArgumentException("the view's up direction " + up + " is parallel to its view direction " + dir);
        }
        if (!(fovDegrees > 0 && fovDegrees < 180)) {
            throw new IllegalArgumentException("the view's field of view must be between 0 and 180 degrees, found " + fovDegrees);
        }
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("the viewport must be at least 1 x 1 pixels, found " + width + " x " + height);
        }
    }
}
