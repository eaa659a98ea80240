package lt.spindulys.render;

import lt.spindulys.image.FrameBuffer;

/**
 * Told when a tile of the frame is finished, for showing a render as it progresses. Called from
 * render threads, each tile once, in no fixed order; implementations synchronise.
 */
@FunctionalInterface
public interface TileListener {
    /**
     * A tile's pixels are final: those of {@code x0 <= x < x1}, {@code y0 <= y < y1} in
     * {@code frame} (linear RGB; see {@link FrameBuffer#toRgb8} for the 8-bit form). The frame is
     * the render's own, shared while it runs: read only this tile's pixels, and only during the
     * call. With several time steps ({@code timesteps}), tiles are reported in the last step only.
     *
     * @param frame the frame being rendered
     * @param x0    the tile's left column
     * @param y0    the tile's top row
     * @param x1    one past its right column
     * @param y1    one past its bottom row
     */
    void tileDone(FrameBuffer frame, int x0, int y0, int x1, int y1);
}
