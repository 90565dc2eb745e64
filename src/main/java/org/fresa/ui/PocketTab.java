package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.GridLayout;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.fresa.chart.PlotScene;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.pocket.MillingDirection;
import org.fresa.post.PocketPost;

/**
 * The Pocket tab: contour file, technology, the recognition tree, the toolpath plot and the NC
 * text. It shows the job's pocket settings (a new job's technology and no contour when the job
 * has none); Compute previews the pocket, and its settings become the job's once the planner
 * accepted them. A bad field is marked, with the reason beside Compute. A program that fails the
 * program check is shown with its failing block marked, and Save program refuses it.
 */
final class PocketTab extends PlotTab {

    private final AppContext ctx;
    private PocketViewModel model = new PocketViewModel();
    // the job's pocket settings the fields show: a job that holds others is shown afresh
    private Optional<PocketSettings> shown = Optional.empty();
    private final JTextArea report = new JTextArea(12, 40);
    private final JTextArea nc = new JTextArea(12, 40);
    private final JTextField contour = new JTextField(24);
    private final JTextField[] tech = new JTextField[PocketViewModel.LABELS.size()];
    private final JComboBox<PocketPost> post = new JComboBox<>(PocketViewModel.POSTS.toArray(new PocketPost[0]));
    private final JComboBox<MillingDirection> direction =
            new JComboBox<>(PocketViewModel.DIRECTIONS.toArray(new MillingDirection[0]));
    private final JComboBox<String> entry = new JComboBox<>(PocketViewModel.ENTRIES.toArray(new String[0]));
    private final JTextField entryAngle = new JTextField(8);
    private final javax.swing.JCheckBox centreCutting = new javax.swing.JCheckBox("Centre-cutting cutter");
    private final JComboBox<String> strategy = new JComboBox<>(PocketViewModel.STRATEGIES.toArray(new String[0]));
    private final JTextField angle = new JTextField(8);
    private final JTextField stockToLeave = new JTextField(8);
    private final JTextField restTool = new JTextField(8);
    private final JComboBox<String> order = new JComboBox<>(PocketViewModel.ORDERS.toArray(new String[0]));
    private final JButton run = new JButton("Compute");
    private final JButton saveProgram = new JButton("Save program...");
    private final JLabel status = new JLabel(" ");
    private final JPanel form = new JPanel();
    private final JTabbedPane texts = new JTabbedPane();
    private final FieldEdits edits = new FieldEdits(() -> fieldsChanged().isEmpty(), this::commit);
    private final PocketContourEditor editor = new PocketContourEditor();
    private final ContourEditorPanel editorPanel =
            new ContourEditorPanel(editor, this::contourEdited, () -> plot.show(editor.scene()), this::saveContour);

    PocketTab(AppContext ctx) {
        super("Pocket");
        this.ctx = ctx;
        form.setLayout(new GridLayout(0, 2, 4, 4));
        JLabel cl = new JLabel("Contour (.dad, .contour)");
        cl.setLabelFor(contour);
        cl.setDisplayedMnemonic('o');
        contour.setName(PocketViewModel.CONTOUR);
        TextChanges.onChange(contour, () -> {
            contourFileChanged();
            edits.typed(contour.getName());
        });
        form.add(cl);
        JPanel file = new JPanel(new BorderLayout());
        file.add(contour, BorderLayout.CENTER);
        JButton browse = new JButton("...");
        browse.getAccessibleContext().setAccessibleName("Choose contour file");
        browse.addActionListener(e -> chooseContour());
        file.add(browse, BorderLayout.EAST);
        form.add(file);
        for (int i = 0; i < tech.length; i++) {
            tech[i] = new JTextField(8);
            tech[i].setName(PocketViewModel.NAMES.get(i));
            String name = tech[i].getName();
            TextChanges.onChange(tech[i], () -> edits.typed(name));
            row(PocketViewModel.LABELS.get(i), (char) 0, tech[i]);
        }
        post.setName("pocket-post");
        post.addActionListener(e -> edits.chosen(null));
        row("Post", 'P', post);
        direction.setName("pocket-direction");
        direction.addActionListener(e -> edits.chosen(null));
        row("Direction (not 7m-compat)", 'D', direction);
        entry.setName(PocketViewModel.ENTRY);
        entry.addActionListener(e -> fieldsChanged());
        row("Entry (not 7m-compat)", 'E', entry);
        entryAngle.setName(PocketViewModel.ENTRY_ANGLE);
        TextChanges.onChange(entryAngle, this::fieldsChanged);
        row(PocketViewModel.ENTRY_ANGLE_LABEL, (char) 0, entryAngle);
        centreCutting.setName(PocketViewModel.CENTRE_CUTTING);
        centreCutting.setMnemonic('u');
        centreCutting.addActionListener(e -> fieldsChanged());
        form.add(new JLabel());
        form.add(centreCutting);
        // the clearing strategy: offset, zigzag or adaptive (G-code and APT posts), each label a keyboard mnemonic
        strategy.setName(PocketViewModel.STRATEGY);
        strategy.addActionListener(e -> fieldsChanged());
        row("Strategy", 'y', strategy);
        angle.setName(PocketViewModel.ANGLE);
        TextChanges.onChange(angle, this::fieldsChanged);
        row(PocketViewModel.ANGLE_LABEL, 'Z', angle);
        stockToLeave.setName(PocketViewModel.STOCK_TO_LEAVE);
        TextChanges.onChange(stockToLeave, this::fieldsChanged);
        row(PocketViewModel.STOCK_TO_LEAVE_LABEL, 'k', stockToLeave);
        order.setName(PocketViewModel.ORDER);
        order.addActionListener(e -> fieldsChanged());
        row("Pass order (offset)", 'r', order);
        // empty: one tool; a diameter: a second, smaller tool (T2) for what the first left
        restTool.setName(PocketViewModel.REST_TOOL);
        TextChanges.onChange(restTool, this::fieldsChanged);
        row(PocketViewModel.REST_TOOL_LABEL, 'T', restTool);
        run.setMnemonic('C');
        run.setName("pocket-compute");
        run.addActionListener(e -> compute());
        form.add(run);
        saveProgram.setName("pocket-save-program");
        saveProgram.setMnemonic('S');
        saveProgram.setToolTipText(
                "Write the computed NC program to a file (a program that fails the check is not" + " written)");
        saveProgram.addActionListener(e -> saveProgram());
        form.add(saveProgram);
        // the reason under the form, as wide as it: a long one wraps instead of being cut off
        status.setName("pocket-status");
        status.setBorder(javax.swing.BorderFactory.createEmptyBorder(4, 4, 4, 4));
        report.setEditable(false);
        nc.setEditable(false);
        nc.setName("pocket-nc");
        report.setFont(new java.awt.Font(java.awt.Font.MONOSPACED, java.awt.Font.PLAIN, 12));
        nc.setFont(report.getFont());
        texts.setName("pocket-texts");
        texts.addTab("Contour elements", editorPanel.component());
        texts.addTab("Recognition tree", new JScrollPane(report));
        texts.addTab("NC program", new JScrollPane(nc));
        JPanel left = new JPanel(new BorderLayout());
        JPanel north = new JPanel(new BorderLayout());
        north.add(form, BorderLayout.NORTH);
        north.add(status, BorderLayout.SOUTH);
        left.add(north, BorderLayout.NORTH);
        left.add(texts, BorderLayout.CENTER);
        panel.add(new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left, plot), BorderLayout.CENTER);
        ctx.model().addListener(e -> {
            if (MainViewModel.DOCUMENT.equals(e.getPropertyName())
                    || MainViewModel.JOB.equals(e.getPropertyName())
                            && !ctx.model().job().pocket().equals(shown)) {
                showJob();
            }
        });
        showJob();
    }

    /** A row of the form: the label, its mnemonic (0 for none), and the field it names. */
    private void row(String label, char mnemonic, JComponent field) {
        JLabel l = new JLabel(label);
        l.setLabelFor(field);
        if (mnemonic != 0) {
            l.setDisplayedMnemonic(mnemonic);
        }
        form.add(l);
        form.add(field);
    }

    /** The job's pocket settings, or a new job's; no result. */
    private void showJob() {
        edits.drop();
        model = new PocketViewModel();
        model.load(ctx.model().job());
        shown = ctx.model().job().pocket();
        edits.fill(() -> {
            contour.setText(model.contourText());
            for (int i = 0; i < tech.length; i++) {
                tech[i].setText(model.value(i));
            }
            post.setSelectedItem(model.post());
            direction.setSelectedItem(model.direction());
            entry.setSelectedItem(model.entry());
            entryAngle.setText(model.entryAngle());
            centreCutting.setSelected(model.centreCutting());
            strategy.setSelectedItem(model.strategy());
            angle.setText(model.angle());
            stockToLeave.setText(model.stockToLeave());
            order.setSelectedItem(model.order());
            restTool.setText(model.restTool());
        });
        report.setText("");
        nc.setText("");
        editor.load(model.editorContour());
        editorPanel.rowsChanged();
        plot.show(contourScene());
        fieldsChanged();
    }

    /**
     * Another contour file named: the editor opens on its records, and the job reads the file
     * again instead of the elements typed before.
     */
    private void contourFileChanged() {
        if (edits.filling()) {
            return;
        }
        model.setContourText(contour.getText());
        try {
            if (!java.nio.file.Files.isRegularFile(Path.of(contour.getText().trim()))) {
                return;
            }
        } catch (java.nio.file.InvalidPathException e) {
            return;
        }
        model.setElements(Optional.empty());
        editor.load(model.editorContour());
        editorPanel.rowsChanged();
        plot.show(contourScene());
    }

    /** The contour Compute will pocket: the elements as typed, else the contour file as read. */
    private PlotScene contourScene() {
        return editor.rows() > 0 ? editor.scene() : model.fileScene();
    }

    /**
     * The typed contour changed: the plot shows it as typed and, when it closes without crossing
     * itself and every cell holds a value, the job holds it (each edit one undo step).
     */
    private void contourEdited() {
        plot.show(editor.scene());
        if (!editor.valid()) {
            return;
        }
        edits.flush();
        model.setElements(Optional.of(editor.contour()));
        commit(null);
    }

    private void saveContour() {
        Optional<String> problem = editor.refusal();
        if (problem.isPresent()) {
            say("The contour is not saved: " + problem.get(), true);
            return;
        }
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.DAD);
        fc.setDialogTitle("Save contour as .dad");
        if (fc.showSaveDialog(panel) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path f = FileChoosers.chosen(fc);
        saveContourTo(f.getFileName().toString().contains(".") ? f : f.resolveSibling(f.getFileName() + ".dad"));
    }

    /**
     * Writes the typed contour as the 1988 program's records (a temporary name, then renamed); the
     * job keeps holding the elements, now under the file's name.
     */
    void saveContourTo(Path file) {
        Optional<String> problem = editor.refusal();
        if (problem.isPresent()) {
            say("The contour is not saved: " + problem.get(), true);
            return;
        }
        try {
            org.fresa.io.AtomicFiles.writeString(file, editor.contour().toDad());
        } catch (java.io.IOException e) {
            say("Cannot save " + file + ": " + e.getMessage(), true);
            return;
        }
        edits.fill(() -> contour.setText(file.toString()));
        edits.flush();
        model.setElements(Optional.of(editor.contour()));
        fieldsChanged();
        commit(null);
        say("Saved " + file, false);
    }

    private void chooseContour() {
        String t = contour.getText().trim();
        JFileChooser ch = FileChoosers.chooser(FileChoosers.Kind.POCKET_CONTOUR);
        if (ch.showOpenDialog(panel) == JFileChooser.APPROVE_OPTION) {
            contour.setText(FileChoosers.chosen(ch).toString());
        }
    }

    /**
     * A field changed: the view model takes it and, when every field is good, the job takes the
     * settings (one undo step per field typed into). A contour that is not yet a file keeps the
     * job's contour: the planner's check of it comes with Compute.
     */
    private void commit(String field) {
        if (edits.filling() || !fieldsChanged().isEmpty()) {
            return;
        }
        Optional<PocketSettings> typed = model.typedSettings();
        if (typed.isEmpty()) {
            return;
        }
        PocketSettings s = typed.get();
        if (s.elements().isEmpty() && !java.nio.file.Files.isRegularFile(s.contour())) {
            Optional<PocketSettings> job = ctx.model().job().pocket();
            if (job.isEmpty()) {
                return;
            }
            s = PocketViewModel.withContour(s, job.get().contour());
        }
        shown = Optional.of(s);
        ctx.model().setJob(ctx.model().job().withPocket(s), field);
    }

    /** Takes the fields into the view model, marks the bad ones and says why beside Compute. */
    private Map<String, String> fieldsChanged() {
        if (edits.filling()) {
            return Map.of();
        }
        model.setContourText(contour.getText());
        for (int i = 0; i < tech.length; i++) {
            model.setValue(i, tech[i].getText());
        }
        model.setPost((PocketPost) post.getSelectedItem());
        model.setDirection((MillingDirection) direction.getSelectedItem());
        model.setEntry((String) entry.getSelectedItem());
        model.setEntryAngle(entryAngle.getText());
        model.setCentreCutting(centreCutting.isSelected());
        model.setStrategy((String) strategy.getSelectedItem());
        model.setAngle(angle.getText());
        model.setStockToLeave(stockToLeave.getText());
        model.setOrder((String) order.getSelectedItem());
        model.setRestTool(restTool.getText());
        Map<String, String> problems = model.problems();
        mark(contour, problems);
        for (JTextField f : tech) {
            mark(f, problems);
        }
        mark(entryAngle, problems);
        mark(angle, problems);
        mark(stockToLeave, problems);
        mark(restTool, problems);
        run.setEnabled(problems.isEmpty());
        run.setToolTipText(
                problems.isEmpty()
                        ? "Plan the pocket and show its passes and program"
                        : "Correct the marked field first");
        say(ProblemMarks.first(problems), !problems.isEmpty());
        return problems;
    }

    /**
     * The line beside Compute; a long reason wraps (HTML) within the label's width instead of
     * being cut off, and stays whole in the tooltip.
     */
    private void say(String text, boolean problem) {
        status.setForeground(problem ? ProblemMarks.PROBLEM : Color.BLACK);
        // Swing's HTML takes CSS pixels as points (4/3 of a screen pixel at 96 dpi)
        ProblemMarks.say(status, text, 40, Math.max(180, (form.getWidth() - 12) * 3 / 4));
    }

    private static void mark(JTextField f, Map<String, String> problems) {
        ProblemMarks.mark(f, problems.get(f.getName()), "Pocket");
    }

    /** Writes the computed program to a chosen file, unless it fails the program check. */
    private void saveProgram() {
        Optional<String> problem = model.saveProblem();
        if (problem.isPresent()) {
            say(problem.get(), true);
            return;
        }
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.NC_PROGRAM);
        fc.setDialogTitle("Save NC program");
        if (fc.showSaveDialog(panel) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        saveProgramTo(FileChoosers.chosen(fc));
    }

    /** Writes the computed program, checked once more, to the file (a temporary name, then renamed). */
    void saveProgramTo(Path file) {
        Optional<String> problem = model.saveProblem();
        if (problem.isPresent()) {
            say(problem.get(), true);
            return;
        }
        PocketSettings s = model.settings();
        String text = model.result().orElseThrow().nc();
        try {
            org.fresa.job.ProgramChecks.require(
                    file.getFileName().toString(),
                    text,
                    org.fresa.job.ProgramChecks.dialect(s.post().word()),
                    org.fresa.job.ProgramChecks.pocket(s));
            org.fresa.io.AtomicFiles.writeString(file, text);
            say("Saved " + file, false);
        } catch (org.fresa.job.ProgramChecks.RefusedProgram e) {
            say(e.getMessage(), true);
        } catch (java.io.IOException e) {
            say("Cannot save " + file + ": " + e.getMessage(), true);
        }
    }

    private void compute() {
        edits.flush();
        if (!fieldsChanged().isEmpty()) {
            return;
        }
        PocketSettings settings = model.typedSettings().orElseThrow();
        model.setSettings(settings);
        PocketViewModel computing = model;
        int generation = ctx.model().generation();
        say("computing", false);
        ctx.tasks()
                .start(
                        "Pocket",
                        progress -> {
                            PocketViewModel.Outcome o = PocketViewModel.outcome(settings, progress);
                            return new Shown(
                                    o,
                                    o.result()
                                            .map(r -> TextDocuments.of(r.report()))
                                            .orElse(null),
                                    o.result()
                                            .map(r -> TextDocuments.of(r.nc()))
                                            .orElse(null));
                        },
                        shown -> {
                            if (computing == model && generation == ctx.model().generation()) {
                                show(settings, shown);
                            }
                        });
    }

    /** An outcome with its texts as documents, filled off the event thread. */
    private record Shown(
            PocketViewModel.Outcome outcome, javax.swing.text.Document report, javax.swing.text.Document nc) {}

    private void show(PocketSettings settings, Shown result) {
        model.show(result.outcome());
        Optional<PocketViewModel.Result> r = model.result();
        if (r.isPresent()) {
            // the planner accepted the settings: they are the job's pocket now
            shown = Optional.of(settings);
            ctx.model().setJob(ctx.model().job().withPocket(settings));
            report.setDocument(result.report());
            nc.setDocument(result.nc());
            nc.setCaretPosition(0);
            plot.show(r.get().scene());
            say(PocketViewModel.doneLine(r.get()), false);
            nc.getHighlighter().removeAllHighlights();
            if (r.get().refusal().isPresent()) {
                org.fresa.check.Failure f = r.get().refusal().get();
                // the program's text, with the failing block marked, in front
                texts.setSelectedIndex(texts.indexOfTab("NC program"));
                ProgramHighlight.line(nc, f.line());
                say("The program is refused and not written: " + f.message(), true);
                ctx.tasks().failed("Pocket program check (" + f.rule().name() + ")");
            }
        } else {
            ctx.tasks().failed("Pocket");
            say(model.error().orElse("The pocket cannot be planned."), true);
        }
    }
}
