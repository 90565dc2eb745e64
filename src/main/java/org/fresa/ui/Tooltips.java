package org.fresa.ui;

import java.awt.Component;
import java.awt.Container;
import java.util.HashMap;
import java.util.Map;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JSlider;
import javax.swing.JSpinner;
import javax.swing.JTable;
import javax.swing.text.JTextComponent;

/**
 * What each input of the tabs means and its unit, shown as the input's tooltip. An input is
 * found by its component name, else by the text of its label, else by its own text (a check
 * box); a tooltip a tab set itself is kept. Lengths are millimetres and angles degrees, as
 * everywhere in the window.
 */
final class Tooltips {

    private static final Map<String, String> TIPS = new HashMap<>();

    private static void tip(String tab, String key, String text) {
        TIPS.put(tab + "|" + key, text);
    }

    static {
        tip("STEP-NC", "stepnc-layer", "Which depth layer of the selected workingstep's toolpath the plot shows");
        tip(
                "STEP-NC",
                "stepnc-replay",
                "Replay position along the toolpath, from its start (left) to its end (right);"
                        + " Page Up/Down and Home/End move it");
        String[] rt = {
            "x of the table in the robot's base frame (mm)",
            "y of the table in the robot's base frame (mm)",
            "z of the table in the robot's base frame (mm)",
            "rotation of the table about the base's z axis (deg)"
        };
        String[] rtKeys = PositionViewModel.ROBOT_TABLE;
        for (int i = 0; i < rtKeys.length; i++) {
            tip("Position", "position-rt-" + rtKeys[i], "Robot -> table: " + rt[i]);
        }
        String[] tp = {
            "x of the workpiece on the table (mm)",
            "y of the workpiece on the table (mm)",
            "z of the workpiece on the table (mm)",
            "rotation of the workpiece about the table's x axis (deg)",
            "rotation of the workpiece about the table's y axis (deg)",
            "rotation of the workpiece about the table's z axis (deg)"
        };
        String[] tpKeys = PositionViewModel.TABLE_PIECE;
        for (int i = 0; i < tpKeys.length; i++) {
            tip("Position", "position-tp-" + tpKeys[i], "Table -> piece: " + tp[i]);
        }
        tip(
                "Position",
                "position-error-axes",
                "Target - reached per axis over the reached points, as"
                        + " summary.json's error_per_axis: x, y, z in mm, the orientation about x, y, z in rad");
        tip(
                "Position",
                "position-place-auto",
                "Searches the robot -> table placement (X, Y, Z, RZ) that reaches every"
                        + " target with the largest joint-limit margin, or says which workingsteps are out of reach (Alt+L)");
        tip("Position", "position-replay", "The trajectory point shown in the cell view and marked in the plots");
        tip("Robot", "robot-choice", "A built-in robot whose Denavit-Hartenberg table and limits fill the editor");
        tip(
                "Robot",
                "robot-dh",
                "Denavit-Hartenberg table, one row per joint: theta and alpha in degrees, d and a in"
                        + " mm, the joint type (R rotary, P prismatic) and its limits (deg or mm); cells take expressions");
        tip("Pocket", "pocket-contour", "The closed line/arc contour to mill (.dad, .contour file)");
        tip(
                "Pocket",
                "pocket-contour-table",
                "The contour's elements as the .dad file holds them, in order of travel:"
                        + " a line by A, B, D (A x + B y = D), an arc by its centre, radius and sense; Insert adds, Delete"
                        + " removes, Alt+Up/Down moves the selected element");
        tip("Pocket", "Tool diameter (mm)", "Diameter of the milling cutter (mm)");
        tip(
                "Pocket",
                "Cut fraction",
                "Step-over between passes as a fraction of the tool diameter (0 to 1; the passes step at least 0.5)");
        tip(
                "Pocket",
                "Finish fraction",
                "Finishing allowance left for the last pass, as a fraction of the tool" + " diameter (0 to 1)");
        tip("Pocket", "Z top (mm)", "Height of the pocket's top face, where cutting starts (mm)");
        tip("Pocket", "Z bottom (mm)", "Height of the pocket's floor (mm), below Z top");
        tip(
                "Pocket",
                "Max depth per pass (mm)",
                "Deepest cut of one level (mm): the depth is split into levels no" + " deeper than this");
        tip("Pocket", "Spindle (rpm)", "Spindle speed (revolutions per minute)");
        tip("Pocket", "Feed (mm/min)", "Feed rate of the roughing passes (mm/min)");
        tip("Pocket", "Finish feed (mm/min)", "Feed rate of the finishing pass (mm/min)");
        tip("Pocket", "Post", "The NC dialect written: 7m-compat reproduces the 1988 thesis program's arithmetic");
        tip(
                "Pocket",
                "Direction (not 7m-compat)",
                "Milling direction of the passes: climb or conventional"
                        + " (the 7m-compat post keeps the thesis program's own)");
        tip(
                "Pocket",
                "Entry (not 7m-compat)",
                "How the cutter goes down into the material: auto (a helix where it"
                        + " has room, else a zig-zag ramp), helix, ramp, or plunge (straight down: only for a centre-cutting"
                        + " cutter; otherwise the program check refuses the program)");
        tip(
                "Pocket",
                PocketViewModel.ENTRY_ANGLE,
                "Steepest descent of a helix or ramp entry, degrees from the floor"
                        + " (0.5 to 90; 3 for a cutter that does not cut at its centre)");
        tip(
                "Pocket",
                PocketViewModel.CENTRE_CUTTING,
                "The cutter cuts at its centre (a slot drill): it may plunge" + " straight down");
        tip(
                "Pocket",
                PocketViewModel.STRATEGY,
                "How the floor is cleared: offset (passes parallel to the walls) or zigzag (parallel lines at"
                        + " the zigzag angle); the finishing pass follows the walls either way. The 7M posts"
                        + " write offset passes only");
        tip(
                "Pocket",
                PocketViewModel.ANGLE,
                "Direction of the zigzag lines, degrees from the x axis (-180 to 180); zigzag only");
        tip(
                "Pocket",
                PocketViewModel.STOCK_TO_LEAVE,
                "Material left on the walls, islands and floor for a later finish (mm, 0 to 10; 0 mills to" + " size)");
        tip(
                "Pocket",
                PocketViewModel.ORDER,
                "Order of the offset passes: from the pocket's middle out to the walls (inside-out) or from"
                        + " the walls in (outside-in); the finishing pass is last either way");
        tip(
                "Pocket",
                PocketViewModel.REST_TOOL,
                "A second, smaller tool (mm; empty for none) that cuts only what the first could not reach:"
                        + " tight corners and narrow necks");
        tip("Cutting", "Kerf (mm):", "Full width of the cut (mm): the path runs half of it off the part");
        tip("Cutting", "Process:", "The cutting process: sets the default speeds, pierce and cut senses");
        tip("Cutting", "Lead-in (mm):", "Length of the approach from the pierce point to the contour (mm)");
        tip("Cutting", "Lead-out (mm):", "Length of the move off the contour after the cut (mm)");
        tip("Cutting", "Lead shape:", "Shape of the leads: a quarter arc or a straight line");
        tip("Cutting", "Overcut (mm):", "How far the cut runs past its start to close the contour cleanly (mm)");
        tip(
                "Cutting",
                "Rapids around cut parts",
                "Route rapid moves around parts already cut, so the head does not" + " cross them");
        tip("Cutting", "Post:", "The NC dialect written");
        tip("Cutting", "Paper mode (2010)", "Plan as the 2010 paper did (its cut order and leads), for comparison");
        tip(
                "Grading",
                "Origin X,Y:",
                "Grading origin (mm, x,y): the point of the base outline that stays fixed" + " while sizes grow");
        tip("Grading", "System:", "Shoe size system of the sizes: br, paris, uk, us or mondopoint");
        tip("Grading", "Base size:", "The size the outline is drawn in, in the chosen system");
        tip("Grading", "Sizes A-B:", "The sizes to grade, from A to B in the chosen system (e.g. 36-44)");
        tip("Grading", "Half sizes", "Grade the half sizes between whole sizes too");
        tip("Grading", "Length step (mm):", "Growth of the sole's length from one size to the next (mm)");
        tip("Grading", "Width step (mm):", "Growth of the sole's width from one size to the next (mm)");
        tip(
                "Grading",
                "Shrinkage:",
                "Allowance for the material's shrinkage in the mould: a factor (multiplicative)"
                        + " or millimetres (additive)");
        tip("Grading", "Shrinkage mode:", "How the shrinkage applies: multiplied with the size or added to it");
        tip("Grading", "grading-table", "Length and width of each graded size (mm)");
        tip("Sole", "sole-designs", "The tread figure placed on the sole, whose parameters the table shows");
        tip("Sole", "sole-parameters", "The selected figure's parameters: value and unit per row (mm, deg)");
        tip("Sole", "sole-size", "The size whose sole the plot shows");
        tip("Sole", "sole-foot", "The foot whose sole the plot shows (the left mirrors the right)");
        tip("Sole", "sole-out", "Folder the sole programs are written to");
        tip("Output", "output-format-csv", "Write trajectory.csv: the joint values (deg, mm) per trajectory point");
        tip(
                "Output",
                "output-format-xml",
                "Write program.xml: the offline-programming XML (schemas/robot-program.xsd)");
        tip("Output", "output-format-rapid", "Write program.mod: the ABB RAPID program");
        tip("Output", "output-format-krl", "Write program.src: the KUKA KRL program");
        tip("Output", "output-format-png", "Write joints.png and error.png: the charts of the trajectory");
        for (String f : new String[] {"csv", "xml", "rapid", "krl", "png"}) {
            tip("Output", "output-preview-" + f, "Show the " + f + " output in the preview");
        }
    }

    private Tooltips() {}

    /** The meaning of a tab's input by its component name or label text, or null when the table has none. */
    static String of(String tab, String key) {
        return TIPS.get(tab + "|" + key);
    }

    /**
     * The meaning of an input by its component name, else by the text of its label; null when the
     * table has none (a field that showed a problem shows its meaning again).
     */
    static String meaning(String tab, JComponent c) {
        String tip = TIPS.get(tab + "|" + c.getName());
        if (tip == null && c.getClientProperty("labeledBy") instanceof JLabel l) {
            tip = TIPS.get(tab + "|" + l.getText());
        }
        return tip;
    }

    /** Sets the tooltip of every input of a tab that has none and that the table knows. */
    static void install(String tab, Component root) {
        if (root instanceof JComponent j
                && isInput(root)
                && (j.getToolTipText() == null || j.getToolTipText().isBlank())) {
            String tip = TIPS.get(tab + "|" + root.getName());
            if (tip == null && j.getClientProperty("labeledBy") instanceof JLabel l) {
                tip = TIPS.get(tab + "|" + l.getText());
            }
            if (tip == null && root instanceof AbstractButton b) {
                tip = TIPS.get(tab + "|" + b.getText());
            }
            if (tip != null && root instanceof JTable t && t.getTableHeader() != null) {
                // a table's cells give their own tooltips (the problem of a cell): its meaning goes
                // on its header, and the cells are not all registered for a tooltip of their own
                t.getTableHeader().setToolTipText(tip);
            } else if (tip != null) {
                j.setToolTipText(tip);
            }
        }
        if (root instanceof Container c
                && !(root instanceof JSpinner)
                && !(root instanceof JComboBox<?>)
                && !(root instanceof JTable)) {
            for (Component child : c.getComponents()) {
                install(tab, child);
            }
        }
    }

    /** A robot parameter's meaning: the robot's name, or a length (mm) or angle (deg) of its geometry. */
    /** The Robot tab's spindle field. */
    static final String SPINDLE = "The spindle nose in the flange frame, as --spindle takes it: X,Y,Z in mm and"
            + " optionally RX,RY,RZ in deg (R = Rz Ry Rx); empty: the robot file's tool frame, else the flange";

    /** The Robot tab's tool length field. */
    static final String TOOL_LENGTH = "The tool's length from the spindle nose to its tip (mm), for every tool, as"
            + " --tool-length; empty: each STEP-NC tool's own length";

    static String robotParameter(String name) {
        if (name.equals("Name")) {
            return "The robot's name, written into its programs";
        }
        return name.startsWith("Tool")
                ? name + ": the tool frame on the flange, "
                        + (name.contains("(deg)") ? "a rotation in degrees" : "an offset in millimetres")
                : name + ": a length of the robot's geometry";
    }

    private static boolean isInput(Component c) {
        return c instanceof JTextComponent t && t.isEditable()
                || c instanceof JComboBox<?>
                || c instanceof JSpinner
                || c instanceof JSlider
                || c instanceof AbstractButton && c instanceof javax.swing.JToggleButton
                || c instanceof JTable;
    }
}
