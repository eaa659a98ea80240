package lt.spindulys.viewer;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.Subdivision;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;

/**
 * One open surface: its mesh and how it is shown (mode, cage over it, level 0..8, scheme,
 * boundary rule), with its display geometry cached per (level, scheme, boundary, shading). The
 * settings belong to the viewer's event thread; {@link #build(Key)} and
 * {@link #control(SubdivOptions.Scheme, SubdivOptions.Boundary)} may run on a background thread.
 */
public final class ViewedSurface {
    /** The level a surface opens at: the deepest up to this whose faces stay under {@link #OPEN_FACES}. */
    static final int OPEN_LEVEL = 3;
    static final long OPEN_FACES = 150_000;
    /**
     * The most faces the viewer shows of one surface. The scene's limit ({@link SubdivisionSurface#MAX_FACES})
     * is for an offline render; the rasterizer draws about ten million quads a second, so past
     * this a frame takes longer than a tenth of a second, and refining to it takes minutes:
     * the level is refused at once instead (the ray-tracing plugin still renders the limit surface).
     */
    static final long MAX_SHOWN_FACES = 1L << 20;
    /** Geometries kept per surface besides the one shown. */
    private static final int CACHED = 3;
    /** And at most this fraction of the heap in them, so that deep levels once shown do not crowd out the next. */
    private static final double CACHED_HEAP_FRACTION = 0.25;

    /**
     * What a geometry is built from.
     *
     * @param level the subdivision level
     * @param scheme the subdivision scheme
     * @param boundary the boundary rule
     * @param smooth smoothed (true) or polyhedron
     */
    record Key(int level, SubdivOptions.Scheme scheme, SubdivOptions.Boundary boundary, boolean smooth) {}

    private final String name;
    private final Path source;
    private final int rgb;
    private SubdivInput input;
    private Path unwrap;
    private DisplayMode mode = DisplayMode.SMOOTHED;
    private boolean cage;
    private int level;
    private SubdivOptions.Scheme scheme;
    private SubdivOptions.Boundary boundary;
    /** The cage's first face that is not a triangle ("face 3 has 4 corners"), which Loop cannot refine; null if all are. */
    private final String nonTriangle;
    private final DisplayGeometry lattice;
    /** Whether the surface has an inside (its topology: the same at every level and under every boundary rule). */
    private final boolean closed;
    /** The control meshes built, by the options (the input's, with the viewer's scheme and boundary rule). */
    private final Map<SubdivOptions, ControlMesh> controls = new HashMap<>();
    private final LinkedHashMap<Key, DisplayGeometry> cache = new LinkedHashMap<>(8, 0.75f, true);
    private DisplayGeometry shown;
    private Key shownKey;
    private Rasterizer.Item facesItem, edgesItem;
    /** The geometry last asked for, read by the background thread to skip work nobody wants any more. */
    private volatile Key requested;

    /**
     * A surface as opened: smoothed at {@link #OPEN_LEVEL} or below, with the scheme and boundary rule of its tags.
     *
     * @param loaded the mesh read
     * @param rgb its colour (0xRRGGBB)
     */
    ViewedSurface(MeshLoader.Loaded loaded, int rgb) {
        this.name = loaded.name();
        this.source = loaded.source();
        this.input = loaded.input();
        this.unwrap = loaded.unwrap();
        this.rgb = rgb;
        this.scheme = input.options().scheme();
        this.boundary = input.options().boundary();
        this.nonTriangle = nonTriangle(input);
        checkShown(0, scheme);
        int l = OPEN_LEVEL;
        while (l > 0 && faces(l, scheme) > OPEN_FACES) l--;
        this.level = l;
        ControlMesh c = control(scheme, boundary);
        this.lattice = DisplayGeometry.lattice(c);
        this.closed = DisplayGeometry.closed(Subdivision.refine(c, 0));
    }

    /** {@return the name shown in the surface list} */
    public String name() { return name; }
    /** {@return the file it was read from} */
    public Path source() { return source; }
    /** {@return the unwrap its UVs came from, or null} */
    public Path unwrap() { return unwrap; }
    /** {@return the mesh as read (with its UVs), before the viewer's scheme and boundary rule} */
    public SubdivInput input() { return input; }
    /** {@return how it is shown} */
    public DisplayMode mode() { return mode; }
    /** {@return whether the cage is drawn over the surface} */
    public boolean cage() { return cage; }
    /** {@return the subdivision level} */
    public int level() { return level; }
    /** {@return the boundary rule} */
    public SubdivOptions.Boundary boundary() { return boundary; }
    /** {@return the subdivision scheme} */
    public SubdivOptions.Scheme scheme() { return scheme; }
    /**
     * The cage's first face that is not a triangle ("face 3 has 4 corners"), why the Loop scheme
     * cannot refine it; null when every face is a triangle.
     *
     * @return the face, or null
     */
    public String nonTriangle() { return nonTriangle; }
    /** {@return its colour (0xRRGGBB)} */
    public int rgb() { return rgb; }
    /** {@return whether the surface is closed: no holes, every edge between two faces} */
    public boolean closed() { return closed; }
    /** {@return the control cage's edges} */
    DisplayGeometry lattice() { return lattice; }

    void mode(DisplayMode m) { mode = m; }
    void cage(boolean c) { cage = c; }
    void boundary(SubdivOptions.Boundary b) { boundary = b; }

    /**
     * Sets the level after the checks a scene's subdivision surface gets: 0..8, and no more faces
     * or heap than that allows.
     *
     * @throws IllegalArgumentException saying why the level is refused; the level stays
     */
    void level(int l) {
        SubdivisionSurface.checkLevel(l, faces(l, scheme));
        checkShown(l, scheme);
        level = l;
    }

    /**
     * Sets the scheme, after the checks a level gets (the faces differ by scheme: a triangle
     * becomes four triangles under Loop, three quads under the others), and refuses Loop on a
     * cage with other faces than triangles.
     *
     * @throws IllegalArgumentException saying why the scheme is refused; the scheme stays
     */
    void scheme(SubdivOptions.Scheme s) {
        // Worded as ControlMesh words it when a Loop file has such a face.
        if (s == SubdivOptions.Scheme.LOOP && nonTriangle != null) throw new IllegalArgumentException(source + ": " + nonTriangle + "; the Loop scheme needs triangles");
        SubdivisionSurface.checkLevel(level, faces(level, s));
        checkShown(level, s);
        scheme = s;
    }

    /** Faces at level {@code l} under scheme {@code s}. */
    private long faces(int l, SubdivOptions.Scheme s) {
        return ControlMesh.refinedFaceCount(s, input.mesh().faceCount(), input.mesh().vertexIndex().length, l);
    }

    /** The first face that is not a triangle ("face 3 has 4 corners"), or null. */
    private static String nonTriangle(SubdivInput in) {
        int[] sizes = in.mesh().faceSizes();
        for (int f = 0; f < sizes.length; f++) {
            if (sizes[f] != 3) return "face " + f + " has " + sizes[f] + " corners";
        }
        return null;
    }

    /** Refuses a level with more faces than the viewer can draw smoothly ({@link #MAX_SHOWN_FACES}). */
    private void checkShown(int l, SubdivOptions.Scheme s) {
        long faces = faces(l, s);
        if (faces > MAX_SHOWN_FACES) {
            throw new IllegalArgumentException(source + ": subdivision level " + l + " would show " + faces
                    + " faces, more than the " + MAX_SHOWN_FACES + " the viewer draws (choose a lower level; the ray-tracing plugin renders the limit surface)");
        }
    }

    /** Takes the settings of {@code k} back (its geometry could not be built; the one shown is {@code k}'s). */
    void settle(Key k) {
        level = k.level();
        scheme = k.scheme();
        boundary = k.boundary();
        if (mode != DisplayMode.LATTICE) mode = k.smooth() ? DisplayMode.SMOOTHED : DisplayMode.POLYHEDRON;
        requested = k;
    }

    /** Replaces the mesh's UVs (an unwrap attached); the geometry does not change. */
    void unwrap(SubdivInput withUvs, Path tex) {
        synchronized (this) {
            input = withUvs;
            controls.clear();
        }
        unwrap = tex;
    }

    /**
     * The input with a scheme and boundary rule in its options.
     *
     * @param s the scheme
     * @param b the boundary rule
     * @return the input
     */
    public synchronized SubdivInput inputWith(SubdivOptions.Scheme s, SubdivOptions.Boundary b) {
        return with(input, s, b);
    }

    private static SubdivInput with(SubdivInput in, SubdivOptions.Scheme s, SubdivOptions.Boundary b) {
        SubdivOptions o = in.options();
        return o.boundary() == b && o.scheme() == s ? in : in.withOptions(o.withScheme(s).withBoundary(b));
    }

    /**
     * The control mesh under a scheme and boundary rule, built once.
     *
     * @param s the scheme
     * @param b the rule
     * @return the control mesh
     */
    ControlMesh control(SubdivOptions.Scheme s, SubdivOptions.Boundary b) {
        SubdivInput from;
        SubdivOptions key;
        synchronized (this) {
            key = input.options().withScheme(s).withBoundary(b);
            ControlMesh c = controls.get(key);
            if (c != null) return c;
            from = input;
        }
        // Built outside the lock: the event thread reads the input (a snapshot for a plugin) while
        // a large mesh's control mesh is built in the background, and must not wait for it.
        ControlMesh built = with(from, s, b).toControlMesh();
        synchronized (this) {
            // Kept only if no unwrap replaced the input meanwhile (its UVs would be missing).
            if (input != from) return built;
            ControlMesh raced = controls.putIfAbsent(key, built);
            return raced != null ? raced : built;
        }
    }

    void requested(Key k) { requested = k; }

    Key requested() { return requested; }

    /** {@return the key of the faces the settings ask for, or null in lattice mode} */
    Key wanted() {
        return mode == DisplayMode.LATTICE ? null : new Key(level, scheme, boundary, mode == DisplayMode.SMOOTHED);
    }

    /**
     * Builds the geometry of {@code k}: refines (off the event thread) and makes the triangles.
     *
     * @param k what to build
     * @return the geometry
     * @throws IllegalArgumentException if the heap no longer allows the level
     */
    DisplayGeometry build(Key k) {
        // Checked again here: other surfaces may have taken the heap since the level was set.
        SubdivisionSurface.checkLevel(k.level(), faces(k.level(), k.scheme()));
        var r = Subdivision.refine(control(k.scheme(), k.boundary()), k.level());
        DisplayGeometry g = k.smooth() ? DisplayGeometry.smoothed(r) : DisplayGeometry.polyhedron(r);
        // The back tint marks faces seen from the inside: a closed surface has one, found from the
        // volume it encloses whatever the file's winding; an open surface's winding decides.
        return closed ? g.outward() : g;
    }

    /** {@return the cached geometry of {@code k}, or null} */
    DisplayGeometry cached(Key k) { return cache.get(k); }

    /** Keeps {@code g} as the geometry of {@code k}, dropping the least recently used beyond the cache's size. */
    void store(Key k, DisplayGeometry g) {
        cache.put(k, g);
        long bytes = 0;
        for (DisplayGeometry d : cache.values()) bytes += d.bytes();
        long cap = (long) (Runtime.getRuntime().maxMemory() * CACHED_HEAP_FRACTION);
        Iterator<Map.Entry<Key, DisplayGeometry>> it = cache.entrySet().iterator();
        while ((cache.size() > CACHED + 1 || bytes > cap) && it.hasNext()) {
            Map.Entry<Key, DisplayGeometry> old = it.next();
            if (old.getKey().equals(shownKey) || old.getKey().equals(k)) continue;
            bytes -= old.getValue().bytes();
            it.remove();
        }
    }

    /** Shows the cached geometry of {@code k} from now on. */
    void show(Key k) {
        DisplayGeometry g = cache.get(k);
        if (g == null || k.equals(shownKey)) return;
        shown = g;
        shownKey = k;
        facesItem = null;
    }

    /** {@return the key of the faces drawn now (perhaps not yet those the settings ask for), or null} */
    Key shownKey() { return shownKey; }

    /** {@return whether the faces drawn are those the settings ask for} */
    boolean upToDate() {
        Key w = wanted();
        return w == null || w.equals(shownKey);
    }

    /** The faces to draw (those last built while newer ones are being built), or null. */
    Rasterizer.Item facesItem() {
        if (mode == DisplayMode.LATTICE || shown == null) return null;
        if (facesItem == null) facesItem = Rasterizer.Item.faces(shown, rgb, backTint(rgb));
        return facesItem;
    }

    /** The cage's edges, or null when not drawn. */
    Rasterizer.Item edgesItem() {
        if (mode != DisplayMode.LATTICE && !cage) return null;
        if (edgesItem == null) edgesItem = Rasterizer.Item.edges(lattice, 0);
        int argb = mode == DisplayMode.LATTICE ? 0xff000000 | lighter(rgb) : 0xff1c1c1c;
        if (edgesItem.lineArgb() != argb) edgesItem = new Rasterizer.Item(lattice, null, null, argb, false, true);
        return edgesItem;
    }

    /** The inside's colour: the surface's mixed with a muted violet, so that inside and outside are told apart. */
    static int backTint(int rgb) {
        return mix(rgb, 0x7a5c99, 0.65);
    }

    private static int lighter(int rgb) { return mix(rgb, 0xffffff, 0.35); }

    private static int mix(int a, int b, double t) {
        int r = (int) Math.round((a >> 16 & 255) * (1 - t) + (b >> 16 & 255) * t);
        int g = (int) Math.round((a >> 8 & 255) * (1 - t) + (b >> 8 & 255) * t);
        int bl = (int) Math.round((a & 255) * (1 - t) + (b & 255) * t);
        return r << 16 | g << 8 | bl;
    }

    /** {@return what an output plugin is handed of this surface} */
    ViewerSnapshot.Surface snapshot() {
        return new ViewerSnapshot.Surface(name, source, inputWith(scheme, boundary), control(scheme, boundary), level, scheme, boundary, mode, cage);
    }
}
