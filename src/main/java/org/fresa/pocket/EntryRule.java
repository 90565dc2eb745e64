package org.fresa.pocket;

import java.util.List;
import org.fresa.model.EnumWords;

/**
 * What the planner may do when the tool goes down into material at the start of a cut: the kind
 * of entry asked for, the steepest descent allowed and whether the tool cuts at its centre.
 *
 * <p>An end mill that does not cut at the centre must never go straight down into material: it
 * enters on a helix or a ramp no steeper than {@code angleDeg} (3 degrees by default, a common
 * limit for such cutters). A straight plunge is made only for a centre-cutting tool, and only
 * when it is asked for or when neither a helix nor a ramp has room.
 *
 * @param kind {@link Kind#AUTO} (a helix where it has room, else a ramp), or one kind asked for
 * @param angleDeg steepest descent of a helix or ramp, measured from the floor (deg, in (0, 90])
 * @param centreCutting whether the tool cuts at its centre (may plunge)
 */
public record EntryRule(Kind kind, double angleDeg, boolean centreCutting) {

    /** The entry angle for a tool that does not cut at the centre when nothing else is said (deg). */
    public static final double DEFAULT_ANGLE_DEG = 3;

    /** Auto entries at 3 degrees for a tool that does not cut at its centre. */
    public static final EntryRule DEFAULT = new EntryRule(Kind.AUTO, DEFAULT_ANGLE_DEG, false);

    /** The kinds of entry, by the names the command line and the job file use. */
    public enum Kind {
        /** A helix where it has room, else a zig-zag ramp (a plunge only for a centre-cutting tool with no room). */
        AUTO,
        /** A helix where it has room, else a ramp. */
        HELIX,
        /** A zig-zag ramp along the cut. */
        RAMP,
        /** Straight down: centre-cutting tools only. */
        PLUNGE;

        /** The name as written: {@code auto}, {@code helix}, {@code ramp}, {@code plunge}. */
        public String word() {
            return EnumWords.of(this);
        }

        /** The kind of a name as written, or empty. */
        public static java.util.Optional<Kind> of(String word) {
            return EnumWords.parse(Kind.class, Kind::word, word);
        }

        /** The names, the default first. */
        public static List<String> words() {
            return EnumWords.all(Kind.class, Kind::word);
        }

        @Override
        public String toString() {
            return word();
        }
    }

    public EntryRule {
        java.util.Objects.requireNonNull(kind, "kind");
        if (!(angleDeg > 0 && angleDeg <= 90)) {
            throw new IllegalArgumentException("entry angle must be in (0, 90] deg: " + angleDeg);
        }
        if (kind == Kind.PLUNGE && !centreCutting) {
            throw new IllegalArgumentException("a plunge entry needs a centre-cutting tool");
        }
    }
}
