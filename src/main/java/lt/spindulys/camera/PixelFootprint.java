package lt.spindulys.camera;

import lt.spindulys.math.Ray;

/**
 * How wide one pixel's footprint is in the scene at a distance along a primary ray:
 * {@code width + distance * spread}. A camera whose rays leave one point (a pinhole, a thin lens's
 * centre rays) has width 0 and spreads by its angle per pixel; an orthographic camera's parallel
 * rays keep the pixel's own width at every distance. Texture filtering sizes its lookups by it.
 *
 * @param width  the footprint's width where the rays start, scene units, at least 0
 * @param spread how much the footprint widens per unit of distance (the angle between neighbouring pixels' rays, radians), at least 0
 */
public record PixelFootprint(double width, double spread) {
    /** Validates. */
    public PixelFootprint {
        if (!(width >= 0 && width < Double.POSITIVE_INFINITY)) throw new IllegalArgumentException("footprint width must be finite and at least 0, found " + width);
        if (!(spread >= 0 && spread < Double.POSITIVE_INFINITY)) throw new IllegalArgumentException("footprint spread must be finite and at least 0, found " + spread);
    }

    /**
     * The footprint's width after a path of this length.
     *
     * @param distance the length travelled from the camera, at least 0
     * @return the width in scene units
     */
    public double at(double distance) { return width + distance * spread; }

    /**
     * The spread of any camera whose rays leave one point, measured between the lens-centre rays
     * through the two pixels at the image centre. Away from the centre a pinhole's pixels subtend
     * slightly less: the approximation errs on the blurrier side there.
     *
     * @param camera the camera
     * @param width  image width in pixels, at least 1
     * @param height image height in pixels, at least 1
     * @return a footprint of width 0 and the measured angle (0 if it cannot be measured)
     */
    public static PixelFootprint measuredAngle(Camera camera, int width, int height) {
        double aspect = (double) width / height;
        Ray a = new Ray(), b = new Ray();
        camera.generateRay(0.5, 0.5, aspect, 0, 0, 0, a);
        camera.generateRay(0.5 + 1.0 / width, 0.5, aspect, 0, 0, 0, b);
        double la = Math.sqrt(a.dx * a.dx + a.dy * a.dy + a.dz * a.dz), lb = Math.sqrt(b.dx * b.dx + b.dy * b.dy + b.dz * b.dz);
        double cos = (a.dx * b.dx + a.dy * b.dy + a.dz * b.dz) / (la * lb);
        double angle = Math.acos(Math.max(-1, Math.min(1, cos)));
        return new PixelFootprint(0, Double.isFinite(angle) ? angle : 0);
    }
}
