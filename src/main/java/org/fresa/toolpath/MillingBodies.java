package org.fresa.toolpath;

import java.util.Set;
import org.fresa.stepnc.Feature;
import org.fresa.stepnc.Tool;

/**
 * Which tool bodies (ISO 14649-111) a milling operation may take into a feature. The planners
 * mill a region sideways and on the tool's end, as an end mill cuts: a drill, tap, reamer, boring
 * bar, countersink or counterbore taken sideways through a pocket breaks; a side mill or thread
 * mill has no end to enter by; a T-slot or dovetail mill is narrower above its cutting part, so
 * only its own feature lets its neck pass; a tapered end mill whose flank leans cuts every upright
 * wall leaning.
 */
final class MillingBodies {

    /** Bodies that cut sideways and on their end as the planners take them. */
    static final Set<String> END_MILLS = Set.of("ENDMILL", "FACEMILL", "BALL_ENDMILL", "BULLNOSE_ENDMILL");

    private MillingBodies() {}

    /**
     * Refuses a tool body that cannot mill this feature as the planner mills it.
     *
     * @throws UnsupportedOperationException naming the body and what mills the feature
     */
    static void check(Tool tool, Feature f) {
        String body = tool.body();
        // a file that names no body gives a milling cutter and nothing more: taken as an end mill
        if (body.isEmpty() || END_MILLS.contains(body)) {
            return;
        }
        if (body.equals("TAPERED_ENDMILL")) {
            double lean = Math.abs(tool.circumferenceAngle().orElse(0));
            if (lean < 1e-9) {
                return;
            }
            throw new UnsupportedOperationException("the TAPERED_ENDMILL's flank leans " + ToolpathPlanner.mm(lean)
                    + " deg (tool_circumference_angle): it would cut the " + what(f) + "'s upright walls leaning;"
                    + " an end mill mills them");
        }
        if ((body.equals("T_SLOT_MILL") || body.equals("DOVETAIL_MILL"))
                && f.type() == Feature.FeatureType.SLOT
                && !(f.profile().orElse(null) instanceof org.fresa.stepnc.Profile.Tee
                        || f.profile().orElse(null) instanceof org.fresa.stepnc.Profile.U)) {
            // a profile the binding did not read: the slot's planner refuses it for what it is
            return;
        }
        if (body.equals("T_SLOT_MILL")
                && f.type() == Feature.FeatureType.SLOT
                && f.profile().orElse(null) instanceof org.fresa.stepnc.Profile.Tee) {
            return;
        }
        if (body.equals("DOVETAIL_MILL")
                && f.type() == Feature.FeatureType.SLOT
                && f.profile().orElse(null) instanceof org.fresa.stepnc.Profile.U u
                && u.entity().equals("SQUARE_U_PROFILE")
                && DovetailSlot.is(u)) {
            return;
        }
        if (body.equals("DOVETAIL_MILL") && f.type() == Feature.FeatureType.STEP) {
            // the step's planner reads its wall and takes the mill only under one that overhangs
            return;
        }
        String only = switch (body) {
            case "T_SLOT_MILL" -> ": it mills a tee slot's cross bar only, its neck being narrower than its disc";
            case "DOVETAIL_MILL" -> ": it mills a dovetail's undercut sides only, being widest at its tip";
            default -> ": it does not cut sideways and on its end as an end mill does";
        };
        throw new UnsupportedOperationException("a " + body + " does not mill a " + what(f) + only
                + "; an ENDMILL, FACEMILL, BALL_ENDMILL or BULLNOSE_ENDMILL mills it");
    }

    /** Bodies that cut on their side only, or are narrower above their cutting part: they cannot go down a hole. */
    static final Set<String> SIDE_CUTTERS =
            Set.of("SIDE_MILL", "T_SLOT_MILL", "DOVETAIL_MILL", "THREAD_MILL", "FACEMILL");

    /**
     * Refuses, for a drilling-type operation, a body that cannot go down its axis into a hole.
     *
     * @throws UnsupportedOperationException naming the body
     */
    static void checkDrilling(Tool tool, String operation) {
        if (SIDE_CUTTERS.contains(tool.body())) {
            throw new UnsupportedOperationException("a " + tool.body() + " does not go down a hole along its axis: a "
                    + operation + " takes a drill, reamer, boring tool, tap, countersink or counterbore");
        }
    }

    private static String what(Feature f) {
        return f.type().name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ');
    }
}
