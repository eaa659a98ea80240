package lt.spindulys.camera;

import java.util.Objects;

import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Ray;

/**
 * A camera carried by keyframed transforms (an animation's keys or a turntable): each ray of the
 * base camera, lens included, is moved by the keys at the ray's own time, so a moving camera
 * blurs the frame as a moving object does. The keys may translate and rotate the camera but not
 * scale it (which would change its lens and its field of view). Immutable.
 */
public final class AnimatedCamera implements Camera {
    private final Camera base;
    private final Keyframes keys;

    /**
     * A camera that moves as {@code keys} say.
     *
     * @param base the camera at rest (a pinhole or a thin lens)
     * @param keys its keyframed transforms, which must not scale
     * @throws IllegalArgumentException if the keys scale or the base is itself animated
     */
    public AnimatedCamera(Camera base, Keyframes keys) {
        this.base = Objects.requireNonNull(base, "base");
        this.keys = Objects.requireNonNull(keys, "keys");
        if (base instanceof AnimatedCamera) throw new IllegalArgumentException("a camera can be animated once: give its keys together");
        if (keys.scales()) throw new IllegalArgumentException("a camera's keys may translate and rotate it but not scale it");
    }

    /** {@return the camera at rest, before the keys move it} */
    public Camera base() { return base; }

    /** {@return the keys that move it} */
    public Keyframes keys() { return keys; }

    /**
     * This animation carrying another camera (for a lens given on the command line).
     *
     * @param other the camera at rest
     * @return the animated camera
     */
    public AnimatedCamera withBase(Camera other) { return new AnimatedCamera(other, keys); }

    /** {@inheritDoc} The keys carry the camera with the new lens. */
    @Override
    public AnimatedCamera withLens(Double aperture, Double focus) { return withBase(base.withLens(aperture, focus)); }

    @Override
    public void generateRay(double fx, double fy, double aspect, double lensU, double lensV, double time, Ray out) {
        base.generateRay(fx, fy, aspect, lensU, lensV, time, out);
        keys.moveRay(time, out);
    }

    @Override public LensPattern lensPattern() { return base.lensPattern(); }

    @Override public boolean usesLens() { return base.usesLens(); }

    @Override public boolean moves() { return true; }

    /** {@inheritDoc} The keys neither scale nor bend the rays: the base camera's. */
    @Override public PixelFootprint pixelFootprint(int width, int height) { return base.pixelFootprint(width, height); }

    /**
     * The camera standing still where it is at {@code time}: for what needs one view of the
     * frame, such as choosing adaptive subdivision levels.
     *
     * @param time a time
     * @return the camera frozen at that time
     */
    public Camera at(double time) {
        return new Camera() {
            @Override public void generateRay(double fx, double fy, double aspect, double lensU, double lensV, double t, Ray out) {
                AnimatedCamera.this.generateRay(fx, fy, aspect, lensU, lensV, time, out);
            }

            // An orthographic base stays orthographic when frozen.
            @Override public PixelFootprint pixelFootprint(int width, int height) { return base.pixelFootprint(width, height); }
        };
    }
}
