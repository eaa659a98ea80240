package lt.spindulys.scene;

import java.util.Locale;

/**
 * A scene's frame range, frame rate and shutter angle. Frame numbers are global: frame N is the
 * instant t = N / fps of the scene's clock (the clock the keys' and motions' times are on), and
 * its shutter is open from t - d / 2 to t + d / 2, where d = (shutter angle / 360) / fps is the
 * exposure (180 degrees: half a frame interval, centred on the frame's time). Every sample of the
 * frame has its own time in that interval, so objects blur along their keys and motions, across
 * keys too. A frame's image depends only on its number, never on which frames were rendered
 * before it: its settings are {@link #settingsFor the scene's with that shutter and a seed mixed
 * from the scene's seed and the frame number}.
 *
 * @param first the first frame, at least 0
 * @param last the last frame, at least {@code first}, at most {@link #MAX_FRAME}
 * @param fps frames per unit of the scene's time (per second), {@link #MIN_FPS} to {@link #MAX_FPS}
 * @param shutterAngle the exposure as a fraction of the frame interval, in degrees: 0 (no motion
 *        blur) to 360 (the whole interval)
 */
public record Animation(int first, int last, double fps, double shutterAngle) {
    /** The largest frame number: the width of {@code ####} padding grows with it, and 7 digits is plenty. */
    public static final int MAX_FRAME = 9_999_999;
    /** The largest frame rate. */
    public static final double MAX_FPS = 1000;
    /**
     * The smallest frame rate: a frame every 1000 units of scene time. Frame times N / fps then
     * stay at most 10^10, and key times (key frames are scene numbers, at most 10^15) at most 10^18,
     * finite whatever the shutter; a rate just above 0 would put every frame but 0 at infinity.
     */
    public static final double MIN_FPS = 0.001;

    /**
     * Checks the values.
     *
     * @throws IllegalArgumentException if a value is out of its range
     */
    public Animation {
        if (first < 0 || first > MAX_FRAME) throw new IllegalArgumentException("first frame must be between 0 and " + MAX_FRAME + ", found " + first);
        if (last < first || last > MAX_FRAME) throw new IllegalArgumentException("last frame must be between the first (" + first + ") and " + MAX_FRAME + ", found " + last);
        if (!(fps >= MIN_FPS && fps <= MAX_FPS)) throw new IllegalArgumentException("fps must be between " + MIN_FPS + " and " + (int) MAX_FPS + ", found " + fmt(fps));
        if (!(shutterAngle >= 0 && shutterAngle <= 360)) throw new IllegalArgumentException("shutter angle must be between 0 and 360 degrees, found " + fmt(shutterAngle));
    }

    /** {@return how many frames the range holds} */
    public int frameCount() { return last - first + 1; }

    /**
     * True if {@code frame} is in the range.
     *
     * @param frame a frame number
     * @return whether first &lt;= frame &lt;= last
     */
    public boolean contains(int frame) { return frame >= first && frame <= last; }

    /**
     * The scene time of a frame (or of a fractional frame, such as a key between frames).
     *
     * @param frame a frame number
     * @return frame / fps
     */
    public double time(double frame) { return frame / fps; }

    /** {@return how long the shutter is open, in scene time: (angle / 360) / fps} */
    public double exposure() { return shutterAngle / 360 / fps; }

    /**
     * The time the shutter opens for {@code frame}.
     *
     * @param frame a frame number
     * @return the frame's time minus half the exposure
     */
    public double shutterOpen(int frame) { return time(frame) - exposure() / 2; }

    /**
     * The time the shutter closes for {@code frame}.
     *
     * @param frame a frame number
     * @return the frame's time plus half the exposure
     */
    public double shutterClose(int frame) { return time(frame) + exposure() / 2; }

    /**
     * The settings to render {@code frame} with: {@code s} with this frame's shutter and
     * {@link #frameSeed its own seed}, so that its noise neither repeats from frame to frame nor
     * depends on other frames rendered before.
     *
     * @param s the scene's settings (command-line overrides applied)
     * @param frame the frame number, in the range
     * @return the frame's settings
     * @throws IllegalArgumentException if the frame is outside the range
     */
    public RenderSettings settingsFor(RenderSettings s, int frame) {
        if (!contains(frame)) throw new IllegalArgumentException("frame " + frame + " is outside the animation's frames " + first + "-" + last);
        return s.toBuilder().shutter(shutterOpen(frame), shutterClose(frame)).seed(frameSeed(s.seed(), frame)).build();
    }

    /**
     * The seed of a frame's random numbers: the scene's seed and the frame number mixed (by
     * SplitMix64's finaliser), a function of those two only.
     *
     * @param seed the scene's seed
     * @param frame the frame number
     * @return the frame's seed
     */
    public static long frameSeed(long seed, int frame) {
        long z = seed + 0x9E3779B97F4A7C15L * (frame + 1L);
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    private static String fmt(double v) { return String.format(Locale.ROOT, "%s", v); }
}
