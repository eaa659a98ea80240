package lt.spindulys.image;

/**
 * A rectangle of a frame's pixels, half-open as pbrt's {@code --pixelbounds}: columns
 * {@code x0 <= x < x1}, rows {@code y0 <= y < y1}, row 0 at the top. A render of a region gives
 * exactly the pixels a render of the whole frame gives there (every sample is seeded from its
 * pixel), so regions rendered apart can be put back together ({@link TileFile}).
 *
 * @param x0 first column
 * @param x1 one past the last column, greater than {@code x0}
 * @param y0 first row
 * @param y1 one past the last row, greater than {@code y0}
 */
public record PixelRegion(int x0, int x1, int y0, int y1) {
    /**
     * Checks that the region is not empty and starts at or after 0.
     *
     * @throws IllegalArgumentException "the region 5,5,0,10 is empty (x1 must be greater than x0)"
     */
    public PixelRegion {
        if (x0 < 0 || y0 < 0) throw new IllegalArgumentException("the region " + text(x0, x1, y0, y1) + " starts before the frame (x0 and y0 must be at least 0)");
        if (x1 <= x0) throw new IllegalArgumentException("the region " + text(x0, x1, y0, y1) + " is empty (x1 must be greater than x0)");
        if (y1 <= y0) throw new IllegalArgumentException("the region " + text(x0, x1, y0, y1) + " is empty (y1 must be greater than y0)");
    }

    /**
     * The whole of a {@code width x height} frame.
     *
     * @param width  pixels across, at least 1
     * @param height pixels down, at least 1
     * @return the region 0,width,0,height
     */
    public static PixelRegion whole(int width, int height) { return new PixelRegion(0, width, 0, height); }

    /**
     * Tile {@code number} of {@code count} (counted from 1) of a {@code width x height} frame: a
     * band of whole rows, rows {@code floor((number - 1) * height / count)} up to
     * {@code floor(number * height / count)}. The bands cover every row exactly once, in order
     * from the top, and differ in height by at most one row; there can be as many as the frame has
     * rows (bands of one row each).
     *
     * @param number which band, {@code 1 <= number <= count}
     * @param count  how many bands, from 1 to {@code height}
     * @param width  the frame's width
     * @param height the frame's height
     * @return the band
     * @throws IllegalArgumentException if {@code number} is outside [1, count] or {@code count} is more than the rows
     */
    public static PixelRegion band(int number, int count, int width, int height) {
        checkTile(number, count);
        if (count > height) {
            throw new IllegalArgumentException("the " + width + "x" + height + " frame has " + height + " row" + (height == 1 ? "" : "s")
                    + ", too few for " + count + " tiles of whole rows");
        }
        int y0 = (int) ((long) (number - 1) * height / count), y1 = (int) ((long) number * height / count);
        return new PixelRegion(0, width, y0, y1);
    }

    /**
     * Refuses a tile number outside [1, count], or a count below 1, before the frame's size is known.
     *
     * @param number which tile
     * @param count  how many tiles
     * @throws IllegalArgumentException "tile 5/4 does not exist (tiles are numbered from 1 to their count)"
     */
    public static void checkTile(int number, int count) {
        if (count < 1 || number < 1 || number > count) {
            throw new IllegalArgumentException("tile " + number + "/" + count + " does not exist (tiles are numbered from 1 to their count)");
        }
    }

    /** {@return the region's width in pixels} */
    public int width() { return x1 - x0; }

    /** {@return the region's height in pixels} */
    public int height() { return y1 - y0; }

    /** {@return the region's pixel count} */
    public long pixels() { return (long) width() * height(); }

    /**
     * Refuses a region that reaches past a {@code width x height} frame.
     *
     * @param width  the frame's width
     * @param height the frame's height
     * @throws IllegalArgumentException "the region 0,300,0,10 reaches past the 200x150 frame (x1 is at most 200)"
     */
    public void checkInside(int width, int height) {
        if (x1 > width) throw new IllegalArgumentException("the region " + this + " reaches past the " + width + "x" + height + " frame (x1 is at most " + width + ")");
        if (y1 > height) throw new IllegalArgumentException("the region " + this + " reaches past the " + width + "x" + height + " frame (y1 is at most " + height + ")");
    }

    /**
     * Tells whether this region and {@code o} share a pixel.
     *
     * @param o another region
     * @return true if they overlap
     */
    public boolean overlaps(PixelRegion o) {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }

    /**
     * Reads {@code X0,X1,Y0,Y1}: four whole numbers separated by commas, as {@link #toString} writes them.
     *
     * @param text the bounds
     * @return the region
     * @throws IllegalArgumentException if the text is not four whole numbers, or they make no region
     */
    public static PixelRegion parse(String text) {
        String[] parts = text.split(",", -1);
        if (parts.length != 4) throw new IllegalArgumentException("expected X0,X1,Y0,Y1 (four whole numbers separated by commas), found '" + text + "'");
        int[] v = new int[4];
        for (int k = 0; k < 4; k++) {
            try {
                v[k] = Integer.parseInt(parts[k].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("expected X0,X1,Y0,Y1 (four whole numbers separated by commas), found '" + text + "'");
            }
        }
        return new PixelRegion(v[0], v[1], v[2], v[3]);
    }

    /** {@return the bounds as {@code X0,X1,Y0,Y1}, the form {@link #parse} reads} */
    @Override
    public String toString() { return text(x0, x1, y0, y1); }

    private static String text(int x0, int x1, int y0, int y1) { return x0 + "," + x1 + "," + y0 + "," + y1; }
}
