package lt.spindulys.scene;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Vec3;

/**
 * A point light with hard shadows. Its contribution at distance d is color * intensity, divided
 * by d^2 when the falloff is {@link Falloff#INVERSE_SQUARE} (physical) and constant with
 * {@link Falloff#NONE} (the thesis's Whitted model). Position components are at most 1e15 in
 * magnitude, colour components 0..100 and intensity 0..1e15 ({@link Ranges}); an inverse-square
 * light's contribution is limited very close to it (see {@link Ranges#MAX_IRRADIANCE}).
 */
public record PointLight(Vec3 position, Color color, double intensity, Falloff falloff) {
    /** How the light's contribution changes with distance. */
    public enum Falloff {
        /** Constant with distance: the thesis's Whitted model. */
        NONE,
        /** Divided by the squared distance: physical. */
        INVERSE_SQUARE
    }

    /**
     * Checks the ranges.
     *
     * @param position where the light is; components at most 1e15 in magnitude
     * @param color its colour, components 0..100
     * @param intensity its strength, 0..1e15
     * @param falloff how its contribution changes with distance
     * @throws IllegalArgumentException naming the component out of range
     */
    public PointLight {
        Ranges.modest("light position", position);
        Ranges.colour("light color", color, Ranges.MAX_COLOUR);
        Ranges.inRange("light intensity", intensity, Ranges.MAX_INTENSITY);
        if (falloff == null) throw new IllegalArgumentException("light falloff is missing");
    }

    /**
     * A white-or-coloured light of intensity 1 with no falloff, as in the thesis.
     *
     * @param position where it is
     * @param color its colour, components 0..100
     */
    public PointLight(Vec3 position, Color color) { this(position, color, 1, Falloff.NONE); }

    /**
     * Intensity times the largest colour component: what the lights' total ({@link Ranges#MAX_TOTAL_LIGHT}) adds up.
     *
     * @return the power
     */
    public double power() { return intensity * color.max(); }
}
