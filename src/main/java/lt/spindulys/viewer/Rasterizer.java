package lt.spindulys.viewer;

import java.util.List;

import lt.spindulys.math.Vec3;

/**
 * The viewer's software rasterizer: a z-buffer over an int ARGB frame, triangles filled scanline by
 * scanline with Gouraud-interpolated headlight shading, and lines (the cage) depth-tested against
 * them with a small bias so that edges lying on a face stay visible.
 *
 * <p>The frame is cut into horizontal bands that a {@link BandPool} of threads takes in turn; a
 * band's pixels are written only by that band, triangles in their fixed order, so the frame is
 * the same for any number of threads. The buffers are reused from frame to frame and grow only
 * when the frame or the geometry does.
 *
 * <p>Shading: a headlight (light from the eye's direction) with Blinn-Phong terms. With the light
 * at the eye the half vector is the light itself, so both terms depend only on n·l; that cosine is
 * computed per normal per frame, interpolated across the triangle and looked up in a 256-entry
 * table per item. Two-sided: a triangle seen from behind (clockwise on screen) is lit with the
 * flipped normal and coloured with the item's back tint, so the inside of an open surface looks
 * lit and is told apart from the outside.
 */
public final class Rasterizer implements AutoCloseable {
    /** Lines pass the depth test this much (relatively) behind the surface, so edges on a face show. */
    static final float LINE_DEPTH_BIAS = 0.004f;
    /** The near plane sits this fraction of the camera's distance in front of the eye. */
    static final double NEAR_FRACTION = 1e-3;
    /** Rows per band at most; small enough that two threads share out uneven frames well. */
    private static final int BAND_ROWS = 32;
    private static final int LEVELS = 256;

    /**
     * One thing to draw: a geometry's triangles (shaded with the front and back tables) and/or its
     * edges (in one colour).
     *
     * @param geometry the arrays
     * @param front shade per level of n·l (256 ARGB entries) of faces seen from the front
     * @param back the same for faces seen from behind
     * @param lineArgb the colour of the edges
     * @param drawTriangles whether the triangles are drawn
     * @param drawEdges whether the edges are drawn
     */
    public record Item(DisplayGeometry geometry, int[] front, int[] back, int lineArgb, boolean drawTriangles, boolean drawEdges) {
        /**
         * A surface's triangles, shaded in {@code rgb} from the front and {@code backRgb} from behind.
         *
         * @param g the geometry
         * @param rgb front colour (0xRRGGBB)
         * @param backRgb back colour (0xRRGGBB)
         * @return the item
         */
        public static Item faces(DisplayGeometry g, int rgb, int backRgb) {
            return new Item(g, shades(rgb), shades(backRgb), 0, true, false);
        }

        /**
         * A geometry's edges in one colour.
         *
         * @param g the geometry
         * @param rgb the colour (0xRRGGBB)
         * @return the item
         */
        public static Item edges(DisplayGeometry g, int rgb) {
            return new Item(g, null, null, 0xff000000 | rgb, false, true);
        }
    }

    /**
     * The table of shades of a colour: ambient, diffuse and a white Blinn-Phong highlight for
     * n·l from 0 to 1.
     *
     * @param rgb the colour (0xRRGGBB)
     * @return 256 ARGB values
     */
    public static int[] shades(int rgb) {
        int[] t = new int[LEVELS];
        double r = (rgb >> 16 & 255) / 255.0, g = (rgb >> 8 & 255) / 255.0, b = (rgb & 255) / 255.0;
        for (int i = 0; i < LEVELS; i++) {
            double c = i / (double) (LEVELS - 1);
            double light = 0.15 + 0.8 * c, spec = 0.3 * Math.pow(c, 40);
            t[i] = 0xff000000 | channel(r * light + spec) << 16 | channel(g * light + spec) << 8 | channel(b * light + spec);
        }
        return t;
    }

    private static int channel(double v) { return (int) Math.round(255 * Math.max(0, Math.min(1, v))); }

    private final BandPool pool;
    // Per-frame inputs, set before the pool runs.
    private List<Item> items;
    private int width, height, bands;
    private int[] frame;
    private float ex, ey, ez, rx, ry, rz, ux, uy, uz, fx, fy, fz, focal, near, cx, cy;
    private int[] background = new int[0];
    private int backgroundHeight = -1;
    // Buffers, grown as needed.
    private float[] depth = new float[0];
    private float[] vx = new float[0], vy = new float[0], vz = new float[0], sx = new float[0], sy = new float[0], sz = new float[0];
    private float[] nl = new float[0];
    private int[] vertexBase = new int[0], normalBase = new int[0], triangleBase = new int[0];
    // Binning: each triangle's first and last band, counts and cursors per (chunk, band), and the
    // triangles of every band in drawing order (band after band).
    private int[] triangleBands = new int[0], binCounts = new int[0], binCursors = new int[0], bandStart = new int[1], binned = new int[0];
    private int triangleTotal;
    private float[][] clip = new float[0][];
    private final java.util.function.IntConsumer transformJob = this::transformChunk, bandJob = this::rasterBand,
            countJob = this::countChunk, fillJob = this::fillChunk;

    /** A rasterizer using every available processor. */
    public Rasterizer() {
        this(Runtime.getRuntime().availableProcessors());
    }

    /**
     * A rasterizer with its own threads.
     *
     * @param threads threads drawing a frame (the caller's included); at least 1
     */
    public Rasterizer(int threads) {
        pool = new BandPool(threads, "spindulys-raster");
    }

    /** {@return the threads drawing a frame} */
    public int threads() { return pool.threads(); }

    /**
     * Draws {@code items} as {@code camera} sees them into {@code frame}, row after row of
     * {@code width} pixels (0xAARRGGBB), over the viewer's background.
     *
     * @param items what to draw, in order
     * @param camera the view
     * @param frame the pixels, at least width * height
     * @param width frame width
     * @param height frame height
     */
    public synchronized void render(List<Item> items, OrbitCamera camera, int[] frame, int width, int height) {
        if (width < 1 || height < 1) return;
        if (frame.length < width * height) throw new IllegalArgumentException("frame has " + frame.length + " pixels, needs " + width * height);
        this.items = items;
        this.frame = frame;
        this.width = width;
        this.height = height;
        setUpView(camera);
        if (depth.length < width * height) depth = new float[width * height];
        if (backgroundHeight != height) background(height);
        int vertices = 0, normals = 0;
        if (vertexBase.length < items.size() + 1) {
            vertexBase = new int[items.size() + 1];
            normalBase = new int[items.size() + 1];
        }
        if (triangleBase.length < items.size() + 1) triangleBase = new int[items.size() + 1];
        int triangles = 0;
        for (int i = 0; i < items.size(); i++) {
            DisplayGeometry g = items.get(i).geometry();
            vertexBase[i] = vertices;
            normalBase[i] = normals;
            triangleBase[i] = triangles;
            vertices += g.vertexCount();
            normals += g.normals().length / 3;
            if (items.get(i).drawTriangles()) triangles += g.triangleCount();
        }
        vertexBase[items.size()] = vertices;
        normalBase[items.size()] = normals;
        triangleBase[items.size()] = triangles;
        triangleTotal = triangles;
        if (triangleBands.length < triangles) triangleBands = new int[Math.max(triangles, triangleBands.length + triangleBands.length / 2)];
        if (vx.length < vertices) {
            int n = Math.max(vertices, vx.length + vx.length / 2);
            vx = new float[n]; vy = new float[n]; vz = new float[n]; sx = new float[n]; sy = new float[n]; sz = new float[n];
        }
        if (nl.length < normals) nl = new float[Math.max(normals, nl.length + nl.length / 2)];
        bands = (height + BAND_ROWS - 1) / BAND_ROWS;
        if (clip.length < bands) {
            clip = new float[bands][];
            for (int b = 0; b < bands; b++) clip[b] = new float[64];
        }
        int chunks = pool.threads() * 4;
        if (binCounts.length < chunks * bands) {
            binCounts = new int[chunks * bands];
            binCursors = new int[chunks * bands];
        }
        if (bandStart.length < bands + 1) bandStart = new int[bands + 1];
        pool.run(chunks, transformJob);
        pool.run(chunks, countJob);
        // Band b's list holds chunk 0's triangles in it, then chunk 1's, ...: the items' order.
        int at = 0;
        for (int b = 0; b < bands; b++) {
            bandStart[b] = at;
            for (int k = 0; k < chunks; k++) {
                binCursors[k * bands + b] = at;
                at += binCounts[k * bands + b];
            }
        }
        bandStart[bands] = at;
        if (binned.length < at) binned = new int[Math.max(at, binned.length + binned.length / 2)];
        pool.run(chunks, fillJob);
        pool.run(bands, bandJob);
        this.items = null;
        this.frame = null;
    }

    private void setUpView(OrbitCamera c) {
        Vec3 e = c.eye(), r = c.right(), u = c.up(), f = c.forward();
        ex = (float) e.x(); ey = (float) e.y(); ez = (float) e.z();
        rx = (float) r.x(); ry = (float) r.y(); rz = (float) r.z();
        ux = (float) u.x(); uy = (float) u.y(); uz = (float) u.z();
        fx = (float) f.x(); fy = (float) f.y(); fz = (float) f.z();
        focal = (float) (height / 2.0 / Math.tan(Math.toRadians(c.fovDegrees()) / 2));
        near = (float) (c.distance() * NEAR_FRACTION);
        cx = width / 2f;
        cy = height / 2f;
    }

    /** A vertical gradient, darker at the bottom. */
    private void background(int h) {
        background = new int[h];
        for (int y = 0; y < h; y++) {
            double t = h == 1 ? 0 : y / (double) (h - 1);
            int r = (int) Math.round(62 - 34 * t), g = (int) Math.round(68 - 36 * t), b = (int) Math.round(80 - 38 * t);
            background[y] = 0xff000000 | r << 16 | g << 8 | b;
        }
        backgroundHeight = h;
    }

    /** Chunk {@code k} of every item's vertices and normals: view space, screen position, n·l. */
    private void transformChunk(int k) {
        int chunks = pool.threads() * 4;
        for (int i = 0; i < items.size(); i++) {
            DisplayGeometry g = items.get(i).geometry();
            float[] p = g.positions();
            int n = g.vertexCount(), base = vertexBase[i];
            int v0 = (int) ((long) n * k / chunks), v1 = (int) ((long) n * (k + 1) / chunks);
            for (int v = v0; v < v1; v++) {
                float dx = p[3 * v] - ex, dy = p[3 * v + 1] - ey, dz = p[3 * v + 2] - ez;
                float x = dx * rx + dy * ry + dz * rz, y = dx * ux + dy * uy + dz * uz, z = dx * fx + dy * fy + dz * fz;
                int o = base + v;
                vx[o] = x; vy[o] = y; vz[o] = z;
                if (z >= near) {
                    float w = 1 / z;
                    sx[o] = cx + focal * x * w;
                    sy[o] = cy - focal * y * w;
                    sz[o] = w;
                }
            }
            float[] nrm = g.normals();
            int nn = nrm.length / 3, nb = normalBase[i];
            int n0 = (int) ((long) nn * k / chunks), n1 = (int) ((long) nn * (k + 1) / chunks);
            // The light comes from the eye: l = -forward.
            for (int m = n0; m < n1; m++) nl[nb + m] = -(nrm[3 * m] * fx + nrm[3 * m + 1] * fy + nrm[3 * m + 2] * fz);
        }
    }

    /** The bands triangle {@code g} (global number) may cover, packed first | last << 16; -1 for none. */
    private int bandsOf(int g, int item) {
        int[] t = items.get(item).geometry().triangles();
        int k = 3 * (g - triangleBase[item]), vb = vertexBase[item];
        int a = vb + t[k], c = vb + t[k + 1], d = vb + t[k + 2];
        float za = vz[a], zc = vz[c], zd = vz[d];
        if (za >= near && zc >= near && zd >= near) {
            float xa = sx[a], xc = sx[c], xd = sx[d];
            if (Math.max(xa, Math.max(xc, xd)) < 0 || Math.min(xa, Math.min(xc, xd)) > width) return -1;
            float ya = sy[a], yc = sy[c], yd = sy[d];
            // The rows whose centres it can reach, as the scanline loop finds them.
            int first = Math.max(0, (int) Math.ceil(Math.min(ya, Math.min(yc, yd)) - 0.5f));
            int last = Math.min(height, (int) Math.ceil(Math.max(ya, Math.max(yc, yd)) - 0.5f));
            if (first >= last) return -1;
            return first / BAND_ROWS | (last - 1) / BAND_ROWS << 16;
        }
        if (za >= near || zc >= near || zd >= near) return (bands - 1) << 16; // cut at the near plane: every band
        return -1;
    }

    /** Chunk {@code k} of the triangles: the bands of each, counted per band. */
    private void countChunk(int k) {
        int chunks = pool.threads() * 4, g0 = (int) ((long) triangleTotal * k / chunks), g1 = (int) ((long) triangleTotal * (k + 1) / chunks);
        int[] counts = binCounts;
        int base = k * bands;
        java.util.Arrays.fill(counts, base, base + bands, 0);
        int item = 0;
        for (int g = g0; g < g1; g++) {
            while (g >= triangleBase[item + 1]) item++;
            int r = bandsOf(g, item);
            triangleBands[g] = r;
            if (r < 0) continue;
            for (int b = r & 0xffff, last = r >>> 16; b <= last; b++) counts[base + b]++;
        }
    }

    /** Chunk {@code k} of the triangles: each written into the lists of its bands, in order. */
    private void fillChunk(int k) {
        int chunks = pool.threads() * 4, g0 = (int) ((long) triangleTotal * k / chunks), g1 = (int) ((long) triangleTotal * (k + 1) / chunks);
        int[] cursor = binCursors;
        int base = k * bands;
        for (int g = g0; g < g1; g++) {
            int r = triangleBands[g];
            if (r < 0) continue;
            for (int b = r & 0xffff, last = r >>> 16; b <= last; b++) binned[cursor[base + b]++] = g;
        }
    }

    /** Band {@code b}: clears its rows, then draws its triangles in the items' order, then every item's edges. */
    private void rasterBand(int b) {
        int y0 = b * BAND_ROWS, y1 = Math.min(height, y0 + BAND_ROWS);
        int w = width;
        for (int y = y0; y < y1; y++) {
            java.util.Arrays.fill(frame, y * w, y * w + w, background[y]);
            java.util.Arrays.fill(depth, y * w, y * w + w, 0f);
        }
        int item = -1, itemEnd = 0, vb = 0, nb = 0, tb = 0;
        int[] t = null, cn = null;
        Item it = null;
        for (int j = bandStart[b], end = bandStart[b + 1]; j < end; j++) {
            int g = binned[j];
            if (g >= itemEnd) {
                do item++; while (g >= triangleBase[item + 1]);
                it = items.get(item);
                t = it.geometry().triangles();
                cn = it.geometry().cornerNormals();
                vb = vertexBase[item];
                nb = normalBase[item];
                tb = triangleBase[item];
                itemEnd = triangleBase[item + 1];
            }
            int k = 3 * (g - tb);
            int a = vb + t[k], c = vb + t[k + 1], d = vb + t[k + 2];
            if (vz[a] >= near && vz[c] >= near && vz[d] >= near) {
                triangle(sx[a], sy[a], sz[a], nl[nb + cn[k]], sx[c], sy[c], sz[c], nl[nb + cn[k + 1]], sx[d], sy[d], sz[d], nl[nb + cn[k + 2]],
                        it, y0, y1);
            } else {
                clipped(a, nl[nb + cn[k]], c, nl[nb + cn[k + 1]], d, nl[nb + cn[k + 2]], it, b, y0, y1);
            }
        }
        for (int i = 0; i < items.size(); i++) {
            Item e = items.get(i);
            if (!e.drawEdges()) continue;
            int[] ed = e.geometry().edges();
            int base = vertexBase[i];
            for (int k = 0; k < ed.length; k += 2) line(base + ed[k], base + ed[k + 1], e.lineArgb(), b, y0, y1);
        }
    }

    /**
     * A triangle crossing the near plane, cut to its part in front (Sutherland-Hodgman against
     * z = near in view space: three or four corners) and drawn as a fan.
     */
    private void clipped(int a, float la, int c, float lc, int d, float ld, Item it, int band, int y0, int y1) {
        float[] in = clip[band];
        // Slots 0..15 take the clipped polygon (at most four corners), 48..59 the three corners.
        source(in, 0, a, la);
        source(in, 1, c, lc);
        source(in, 2, d, ld);
        int n = 0;
        for (int j = 0; j < 3; j++) {
            int p = 48 + 4 * j, q = 48 + 4 * ((j + 1) % 3);
            boolean pin = in[p + 2] >= near, qin = in[q + 2] >= near;
            if (pin) n = put(in, n, in[p], in[p + 1], in[p + 2], in[p + 3]);
            if (pin != qin) {
                float t = (near - in[p + 2]) / (in[q + 2] - in[p + 2]);
                n = put(in, n, in[p] + t * (in[q] - in[p]), in[p + 1] + t * (in[q + 1] - in[p + 1]), near, in[p + 3] + t * (in[q + 3] - in[p + 3]));
            }
        }
        for (int j = 0; j < n; j++) {
            float z = in[4 * j + 2], w = 1 / Math.max(z, near);
            float x = cx + focal * in[4 * j] * w, y = cy - focal * in[4 * j + 1] * w;
            in[4 * j] = x;
            in[4 * j + 1] = y;
            in[4 * j + 2] = w;
        }
        for (int j = 1; j + 1 < n; j++) {
            triangle(in[0], in[1], in[2], in[3], in[4 * j], in[4 * j + 1], in[4 * j + 2], in[4 * j + 3],
                    in[4 * j + 4], in[4 * j + 5], in[4 * j + 6], in[4 * j + 7], it, y0, y1);
        }
    }

    private void source(float[] in, int j, int v, float l) {
        int o = 48 + 4 * j;
        in[o] = vx[v]; in[o + 1] = vy[v]; in[o + 2] = vz[v]; in[o + 3] = l;
    }

    private static int put(float[] a, int n, float x, float y, float z, float l) {
        a[4 * n] = x; a[4 * n + 1] = y; a[4 * n + 2] = z; a[4 * n + 3] = l;
        return n + 1;
    }

    /**
     * Fills a screen-space triangle within rows y0..y1-1: pixels whose centres are inside (a
     * centre on the left edge in, on the right edge out, so shared edges are drawn once), depth
     * 1/z and n·l interpolated linearly on screen (1/z is linear there), nearer depth wins,
     * the first drawn on a tie.
     */
    private void triangle(float x0, float y0, float z0, float l0, float x1, float y1, float z1, float l1,
                          float x2, float y2, float z2, float l2, Item it, int rowFrom, int rowTo) {
        float area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
        if (!(area != 0) || Float.isInfinite(area)) return;
        // Counter-clockwise in the world's right-handed view is clockwise on a y-down screen: front.
        boolean front = area < 0;
        int[] lut = front ? it.front() : it.back();
        float sign = front ? 255f : -255f;
        float inv = 1 / area;
        float dzdx = ((z1 - z0) * (y2 - y0) - (z2 - z0) * (y1 - y0)) * inv;
        float dzdy = ((z2 - z0) * (x1 - x0) - (z1 - z0) * (x2 - x0)) * inv;
        float dldx = ((l1 - l0) * (y2 - y0) - (l2 - l0) * (y1 - y0)) * inv;
        float dldy = ((l2 - l0) * (x1 - x0) - (l1 - l0) * (x2 - x0)) * inv;
        // Sort by y: a top, b middle, c bottom.
        float ax = x0, ay = y0, bx = x1, by = y1, cxv = x2, cyv = y2, t;
        if (by < ay) { t = ax; ax = bx; bx = t; t = ay; ay = by; by = t; }
        if (cyv < by) { t = bx; bx = cxv; cxv = t; t = by; by = cyv; cyv = t; }
        if (by < ay) { t = ax; ax = bx; bx = t; t = ay; ay = by; by = t; }
        int first = Math.max(rowFrom, (int) Math.ceil(ay - 0.5f)), last = Math.min(rowTo, (int) Math.ceil(cyv - 0.5f));
        int w = width;
        float[] zb = depth;
        int[] px = frame;
        // Every edge is evaluated the same way, from its upper end with its own slope, whichever
        // role (long or short side) it has here: the triangle across it evaluates it to the very
        // same float, so a pixel centre on a shared edge goes to exactly one of the two. (The short
        // sides computed as (yc - ay) * dx / dy rounded differently from the long side's
        // (yc - ay) * slope, and a centre on a shared diagonal could fall in neither: a pinhole.)
        // A slope across a flat side is infinite or NaN but never used: no row centre lies in it.
        float longSlope = (cxv - ax) / (cyv - ay), upperSlope = (bx - ax) / (by - ay), lowerSlope = (cxv - bx) / (cyv - by);
        for (int y = first; y < last; y++) {
            float yc = y + 0.5f;
            float xl = ax + (yc - ay) * longSlope, xr;
            if (yc < by) xr = ax + (yc - ay) * upperSlope;
            else xr = bx + (yc - by) * lowerSlope;
            if (xr < xl) { t = xl; xl = xr; xr = t; }
            int xs = Math.max(0, (int) Math.ceil(xl - 0.5f)), xe = Math.min(w, (int) Math.ceil(xr - 0.5f));
            if (xs >= xe) continue;
            float fx0 = xs + 0.5f - x0, fy0 = yc - y0;
            float z = z0 + fx0 * dzdx + fy0 * dzdy, l = (l0 + fx0 * dldx + fy0 * dldy) * sign;
            float dl = dldx * sign;
            for (int i = y * w + xs, end = y * w + xe; i < end; i++, z += dzdx, l += dl) {
                if (z > zb[i]) {
                    zb[i] = z;
                    int s = (int) (l + 0.5f);
                    px[i] = lut[s < 0 ? 0 : s > 255 ? 255 : s];
                }
            }
        }
    }

    /** An edge within rows y0..y1-1: cut at the near plane and to the band, then stepped pixel by pixel. */
    private void line(int p, int q, int argb, int band, int rowFrom, int rowTo) {
        float zp = vz[p], zq = vz[q];
        if (zp < near && zq < near) return;
        float x0, y0, w0, x1, y1, w1;
        if (zp >= near) { x0 = sx[p]; y0 = sy[p]; w0 = sz[p]; } else {
            float t = (near - zp) / (zq - zp), w = 1 / near;
            x0 = cx + focal * (vx[p] + t * (vx[q] - vx[p])) * w;
            y0 = cy - focal * (vy[p] + t * (vy[q] - vy[p])) * w;
            w0 = w;
        }
        if (zq >= near) { x1 = sx[q]; y1 = sy[q]; w1 = sz[q]; } else {
            float t = (near - zq) / (zp - zq), w = 1 / near;
            x1 = cx + focal * (vx[q] + t * (vx[p] - vx[q])) * w;
            y1 = cy - focal * (vy[q] + t * (vy[p] - vy[q])) * w;
            w1 = w;
        }
        // Liang-Barsky against the frame's width and the band's rows.
        float dx = x1 - x0, dy = y1 - y0;
        float[] tt = clip[band];
        tt[60] = 0;
        tt[61] = 1;
        if (!cut(tt, -dx, x0) || !cut(tt, dx, width - x0) || !cut(tt, -dy, y0 - rowFrom) || !cut(tt, dy, rowTo - y0)) return;
        float t0 = tt[60], t1 = tt[61];
        float ax = x0 + t0 * dx, ay = y0 + t0 * dy, aw = w0 + t0 * (w1 - w0);
        float bx = x0 + t1 * dx, by = y0 + t1 * dy, bw = w0 + t1 * (w1 - w0);
        int steps = (int) Math.ceil(Math.max(Math.abs(bx - ax), Math.abs(by - ay)));
        float inv = steps == 0 ? 0 : 1f / steps;
        float[] zb = depth;
        int[] px = frame;
        for (int s = 0; s <= steps; s++) {
            float f = s * inv;
            int x = (int) (ax + f * (bx - ax)), y = (int) (ay + f * (by - ay));
            if (x < 0 || x >= width || y < rowFrom || y >= rowTo) continue;
            int i = y * width + x;
            float z = aw + f * (bw - aw);
            if (z * (1 + LINE_DEPTH_BIAS) >= zb[i]) px[i] = argb;
        }
    }

    /** One Liang-Barsky boundary: narrows [tt[60], tt[61]]; false when nothing is left. */
    private static boolean cut(float[] tt, float p, float q) {
        if (p == 0) return q >= 0;
        float r = q / p;
        if (p < 0) { if (r > tt[60]) tt[60] = r; } else if (r < tt[61]) tt[61] = r;
        return tt[60] <= tt[61];
    }

    /** Stops the drawing threads. */
    @Override
    public void close() { pool.close(); }
}
