package lt.spindulys.camera;

import lt.spindulys.math.Ray;

/** Turns a point on the film (and a lens sample and a time) into a primary ray. Immutable. */
public interface Camera {
    /**
     * Writes the world-space ray through film position (fx, fy) into {@code out}.
     *
     * @param fx     0 at the left edge of the image, 1 at the right
     * @param fy     0 at the top edge, 1 at the bottom
     * @param aspect image width / height
     * @param lensU  lens sample in [0, 1)
     * @param lensV  lens sample in [0, 1)
     * @param time   time in the shutter interval
     */
    void generateRay(double fx, double fy, double aspect, double lensU, double lensV, double time, Ray out);
}
