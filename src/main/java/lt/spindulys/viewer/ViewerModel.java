package lt.spindulys.viewer;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Executor;

import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.math.Bounds;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;

/**
 * What the viewer does, without a window: the open surfaces and the selected one, the camera
 * and the viewport, and every action of the menus, keys and mouse. Belongs to one thread (the
 * event thread in the viewer, the test's thread in tests). Reading files and refining run on
 * the {@code background} executor; their results come back through the {@code ui} executor, so
 * the state only ever changes on the owning thread. Failures reach {@link Listener#error} as the
 * one line the command line prints, and change nothing.
 */
public final class ViewerModel {
    /** Hears about changes. */
    public interface Listener {
        /** Something shown changed: repaint, update the list and the menus. */
        void changed();

        /**
         * Only the camera moved (orbit, pan, zoom): a repaint is enough. Called for every mouse
         * drag step, so a host keeps it cheap; by default it is {@link #changed()}.
         */
        default void viewChanged() { changed(); }

        /**
         * An action failed.
         *
         * @param message the one-line message
         */
        void error(String message);
    }

    /** Surface colours, in the order surfaces are opened. */
    static final int[] PALETTE = {0xd9a441, 0x6fa8dc, 0x8bc46a, 0xe07a6a, 0xb4a0e0, 0x5fc4c0, 0xe0a0c8, 0xc8c8c8};

    private final Executor background, ui;
    private final Listener listener;
    private final List<ViewedSurface> surfaces = new ArrayList<>();
    private final Set<Object> building = new HashSet<>();
    private final OrbitCamera camera = new OrbitCamera();
    private int selected = -1, width = 640, height = 480, opened, pending;
    private List<Rasterizer.Item> drawList;

    /**
     * A viewer with nothing open.
     *
     * @param background runs file reading and refinement
     * @param ui runs their results on the owning thread
     * @param listener hears about changes and failures
     */
    public ViewerModel(Executor background, Executor ui, Listener listener) {
        this.background = background;
        this.ui = ui;
        this.listener = listener;
    }

    /** {@return the open surfaces, in the list's order} */
    public List<ViewedSurface> surfaces() { return Collections.unmodifiableList(surfaces); }
    /** {@return the index of the selected surface, or -1} */
    public int selectedIndex() { return selected; }
    /** {@return the selected surface, or null} */
    public ViewedSurface selected() { return selected < 0 ? null : surfaces.get(selected); }
    /** {@return the camera (change it through the model's actions, so that the listener hears)} */
    public OrbitCamera camera() { return camera; }
    /** {@return the viewport's width} */
    public int width() { return width; }
    /** {@return the viewport's height} */
    public int height() { return height; }
    /** {@return files being read and geometries being built} */
    public int pending() { return pending; }

    /**
     * Selects a surface.
     *
     * @param index its index, or -1 for none
     */
    public void select(int index) {
        if (index < -1 || index >= surfaces.size()) throw new IndexOutOfBoundsException("no surface " + index + " (" + surfaces.size() + " open)");
        if (index == selected) return;
        selected = index;
        changed();
    }

    /**
     * The viewport's size, for fitting and panning.
     *
     * @param w width in pixels
     * @param h height in pixels
     */
    public void viewport(int w, int h) {
        width = Math.max(1, w);
        height = Math.max(1, h);
    }

    // ---- files ----

    /**
     * Opens files: meshes become new surfaces (read in the background, added in order, then the
     * view fits them all and the last becomes the selected one); a {@code .tex} unwrap is
     * attached to the selected surface (or to the mesh opened just before it in the same list).
     *
     * @param files the files
     */
    public void open(List<Path> files) {
        for (Path f : files) {
            if (MeshLoader.isUnwrap(f)) {
                attachUnwrap(f);
                continue;
            }
            int color = PALETTE[opened++ % PALETTE.length];
            pending++;
            background.execute(() -> {
                ViewedSurface s;
                try {
                    s = new ViewedSurface(MeshLoader.load(f), color);
                } catch (Throwable t) {
                    fail(t);
                    return;
                }
                ui.execute(() -> {
                    pending--;
                    surfaces.add(s);
                    selected = surfaces.size() - 1;
                    fit();
                    refresh(s);
                });
            });
        }
    }

    /** Attaches an unwrap to the selected surface, once the meshes opened before it are in. */
    private void attachUnwrap(Path tex) {
        pending++;
        // Through both executors, so that it follows the meshes opened before it in the same list.
        background.execute(() -> ui.execute(() -> {
            pending--;
            ViewedSurface s = selected();
            if (s == null) {
                listener.error(FailureMessage.of(new IllegalArgumentException(tex + ": an unwrap (.tex) is attached to the selected surface, but no surface is open")));
                return;
            }
            SubdivInput in = s.input();
            pending++;
            background.execute(() -> {
                SubdivInput withUvs;
                try {
                    withUvs = MeshLoader.withUnwrap(in, tex);
                    withUvs.toControlMesh();
                } catch (Throwable t) {
                    fail(t);
                    return;
                }
                ui.execute(() -> {
                    pending--;
                    if (surfaces.contains(s)) {
                        s.unwrap(withUvs, tex);
                        changed();
                    }
                });
            });
        }));
    }

    /** Reports a background failure on the owning thread. */
    private void fail(Throwable t) {
        String m = FailureMessage.of(t);
        ui.execute(() -> {
            pending--;
            listener.error(m);
            changed();
        });
    }

    /** Closes the selected surface; the one after it (or before, at the end) becomes selected. */
    public void closeSelected() {
        if (selected < 0) return;
        surfaces.remove(selected);
        if (selected >= surfaces.size()) selected = surfaces.size() - 1;
        changed();
    }

    // ---- view ----

    /** Fits the view to every open surface (their control points, which contain the surfaces). */
    public void fit() {
        Bounds b = Bounds.EMPTY;
        for (ViewedSurface s : surfaces) b = b.union(s.lattice().bounds());
        camera.fit(b, width / (double) height);
        changed();
    }

    /**
     * Turns the view as a mouse drag does.
     *
     * @param dx pixels right
     * @param dy pixels down
     */
    public void orbit(double dx, double dy) {
        camera.orbit(dx, dy);
        viewChanged();
    }

    /**
     * Moves the view as a mouse drag does.
     *
     * @param dx pixels right
     * @param dy pixels down
     */
    public void pan(double dx, double dy) {
        camera.pan(dx, dy, height);
        viewChanged();
    }

    /**
     * Moves the eye closer (factor above 1) or farther.
     *
     * @param factor times closer
     */
    public void zoom(double factor) {
        camera.zoom(factor);
        viewChanged();
    }

    // ---- the selected surface ----

    /**
     * Shows the selected surface in {@code m}.
     *
     * @param m the mode
     */
    public void mode(DisplayMode m) {
        ViewedSurface s = selected();
        if (s == null || s.mode() == m) return;
        s.mode(m);
        refresh(s);
    }

    /** Draws the selected surface's cage over it, or stops. */
    public void toggleCage() {
        ViewedSurface s = selected();
        if (s == null) return;
        s.cage(!s.cage());
        changed();
    }

    /** One level deeper on the selected surface, if it is allowed. */
    public void levelUp() {
        ViewedSurface s = selected();
        if (s != null) level(s.level() + 1);
    }

    /** One level shallower on the selected surface, down to 0. */
    public void levelDown() {
        ViewedSurface s = selected();
        if (s != null && s.level() > 0) level(s.level() - 1);
    }

    /**
     * Sets the selected surface's level; a level that is refused (past 8, or more faces or heap
     * than allowed) is reported and changes nothing.
     *
     * @param l the level
     */
    public void level(int l) {
        ViewedSurface s = selected();
        if (s == null || s.level() == l) return;
        try {
            s.level(l);
        } catch (IllegalArgumentException e) {
            listener.error(FailureMessage.of(e));
            return;
        }
        refresh(s);
    }

    /**
     * Sets the selected surface's boundary rule.
     *
     * @param b the rule
     */
    public void boundary(SubdivOptions.Boundary b) {
        ViewedSurface s = selected();
        if (s == null || s.boundary() == b) return;
        s.boundary(b);
        refresh(s);
    }

    /**
     * Sets the selected surface's subdivision scheme; a scheme that is refused (Loop on a cage
     * with faces that are not triangles, or one whose level has too many faces) is reported and
     * changes nothing.
     *
     * @param sc the scheme
     */
    public void scheme(SubdivOptions.Scheme sc) {
        ViewedSurface s = selected();
        if (s == null || s.scheme() == sc) return;
        try {
            s.scheme(sc);
        } catch (IllegalArgumentException e) {
            listener.error(FailureMessage.of(e));
            return;
        }
        refresh(s);
    }

    /** Shows what {@code s}'s settings ask for: from the cache, or built in the background. */
    private void refresh(ViewedSurface s) {
        ViewedSurface.Key k = s.wanted();
        if (k == null || s.cached(k) != null) {
            // Also what is requested now, so that a queued build of an older setting is skipped.
            s.requested(k);
            if (k != null) s.show(k);
            changed();
            return;
        }
        s.requested(k);
        changed();
        Object job = List.of(s, k);
        if (!building.add(job)) return;
        pending++;
        background.execute(() -> {
            // Settings changed faster than refinement: a geometry nobody wants now is not built.
            if (!k.equals(s.requested())) {
                ui.execute(() -> {
                    pending--;
                    building.remove(job);
                    // Asked for again after this job was skipped but before it left the set: that
                    // request found the job still "building" and queued nothing, so queue it now.
                    if (surfaces.contains(s) && k.equals(s.wanted()) && s.cached(k) == null) refresh(s);
                });
                return;
            }
            DisplayGeometry g;
            try {
                g = s.build(k);
            } catch (Throwable t) {
                ui.execute(() -> {
                    building.remove(job);
                    // What is on screen stays, and the settings go back to what it shows.
                    if (surfaces.contains(s) && k.equals(s.wanted()) && s.shownKey() != null) s.settle(s.shownKey());
                });
                fail(t);
                return;
            }
            ui.execute(() -> {
                pending--;
                building.remove(job);
                if (!surfaces.contains(s)) return;
                s.store(k, g);
                if (k.equals(s.wanted())) s.show(k);
                changed();
            });
        });
    }

    private void changed() {
        drawList = null;
        listener.changed();
    }

    /** The camera moved: what is drawn (the draw list) stays, so a frame while orbiting allocates nothing. */
    private void viewChanged() {
        listener.viewChanged();
    }

    /**
     * What the rasterizer draws: every surface's faces, then the cages (so they are depth tested
     * against every surface). The same list until something changes.
     *
     * @return the items
     */
    public List<Rasterizer.Item> drawList() {
        if (drawList == null) {
            List<Rasterizer.Item> items = new ArrayList<>();
            for (ViewedSurface s : surfaces) if (s.facesItem() != null) items.add(s.facesItem());
            for (ViewedSurface s : surfaces) if (s.edgesItem() != null) items.add(s.edgesItem());
            drawList = List.copyOf(items);
        }
        return drawList;
    }

    /**
     * What an output plugin is handed: every surface and the view, as they are now.
     *
     * @return the snapshot
     */
    public ViewerSnapshot snapshot() {
        List<ViewerSnapshot.Surface> list = new ArrayList<>();
        for (ViewedSurface s : surfaces) list.add(s.snapshot());
        return new ViewerSnapshot(list, new ViewerSnapshot.View(camera.eye(), camera.target(), camera.up(), camera.fovDegrees(), width, height));
    }
}
