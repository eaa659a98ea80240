package lt.spindulys.render;

/** The renderer's tile order and tile size for tests outside this package (the command line's progress bar). */
public final class TileOrder {
    private TileOrder() {}

    /** Tile side in pixels ({@link Renderer#TILE}). */
    public static final int TILE = Renderer.TILE;

    /** The tile handed out {@code k}-th of {@code tiles}, in the renderer's order ({@link Renderer#tileAt}). */
    public static int tileAt(int k, int tiles, int stride) {
        return Renderer.tileAt(k, tiles, stride);
    }

    /** The stride of that order for {@code tiles} tiles ({@link Renderer#spreadStride}). */
    public static int spreadStride(int tiles) {
        return Renderer.spreadStride(tiles);
    }
}
