package lt.spindulys.scene;

import lt.spindulys.limits.MessageText;

/**
 * An object refused while {@link SceneBuilder#build()} freezes the scene (a transform that
 * becomes singular or overflows once composed with an enclosing object's, a motion whose times do
 * not fit the shutter), named by where it was made: its {@link GObject#source()}, as in
 * {@code "scene.dat:12:3: sphere: transform is singular (a scale of zero?)"}; or, for an
 * object without one, by its place in the scene: {@code "object 2 (union), operand 1 (sphere
 * 'ball'): ..."} (counted from 1). {@link #problem()} is the refusal alone. Like
 * {@code SceneException}'s, the message is one line (unprintable characters escaped).
 */
public final class SceneBuildException extends IllegalArgumentException {
    /** The refusal without the object that caused it. */
    private final String problem;
    /** The source of the nearest object, from the one refused outwards, that has one; null until one does. */
    private String source;
    /** The outermost object named so far, and the path from it to the refused object. */
    private String head, tail = "";

    private SceneBuildException(GObject o, IllegalArgumentException cause) {
        super(cause.getMessage(), cause);
        this.problem = String.valueOf(cause.getMessage());
        this.head = o.label();
        this.source = o.source();
    }

    /** {@code e} as a refusal of {@code o}; one already attributed (to an object inside {@code o}) is returned as it is. */
    static SceneBuildException of(GObject o, IllegalArgumentException e) {
        return e instanceof SceneBuildException b ? b : new SceneBuildException(o, e);
    }

    /** Names the refused object as operand {@code index} (from 0) of {@code container}, unless a source already places it. */
    SceneBuildException inOperand(GObject container, int index) {
        if (source == null) {
            tail = ", operand " + (index + 1) + " (" + head + ")" + tail;
            head = container.label();
            source = container.source();
        }
        return this;
    }

    /** Names the refused object's outermost object as the scene's object {@code index} (from 0), unless a source places it. */
    SceneBuildException inScene(int index) {
        if (source == null) head = "object " + (index + 1) + " (" + head + ")";
        return this;
    }

    /**
     * The refusal without the object: "transform is singular (a scale of zero?)".
     *
     * @return the refusal alone
     */
    public String problem() { return problem; }

    /**
     * The source of the object that places the message (see {@link GObject#source()}), or null.
     *
     * @return the source, or null
     */
    public String source() { return source; }

    @Override public String getMessage() {
        return MessageText.escape((source != null ? source + ": " : "") + head + tail + ": " + problem);
    }
}
