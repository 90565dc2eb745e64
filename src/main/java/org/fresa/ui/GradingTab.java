package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.JToggleButton;
import javax.swing.table.DefaultTableModel;
import org.fresa.grading.GradingResult;
import org.fresa.grading.ShrinkageMode;
import org.fresa.grading.SizeSystem;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;

/**
 * The Grading tab: a base outline, the grading options (origin typed or picked on the plot,
 * system, base size, range, steps, shrinkage), the nested graded outlines and the grading table,
 * and Export of every size's files. The state lives in {@link GradingViewModel}.
 */
final class GradingTab extends PlotTab {

    private final AppContext ctx;
    private GradingViewModel vm = new GradingViewModel();
    // the job's grading settings the fields show: a job that holds others is shown afresh
    private Optional<GradingSettings> shown = Optional.empty();
    private final DefaultTableModel tableModel = new DefaultTableModel(GradingViewModel.COLUMNS.toArray(), 0) {
        private static final long serialVersionUID = 1L;

        @Override
        public boolean isCellEditable(int row, int column) {
            return false;
        }
    };
    private final JLabel outlineName = new JLabel("(none)");
    private final JTextField origin = new JTextField(12);
    private final JToggleButton pick = new JToggleButton("Pick on plot");
    private final JComboBox<SizeSystem> system = new JComboBox<>(GradingViewModel.SYSTEMS.toArray(new SizeSystem[0]));
    private final JTextField baseSize = new JTextField(6);
    private final JTextField sizes = new JTextField(8);
    private final JCheckBox halfSizes = new JCheckBox("Half sizes");
    private final JTextField lengthStep = new JTextField(6);
    private final JTextField widthStep = new JTextField(6);
    private final JTextField shrinkage = new JTextField(6);
    private final JComboBox<ShrinkageMode> shrinkageMode =
            new JComboBox<>(GradingViewModel.SHRINKAGE_MODES.toArray(new ShrinkageMode[0]));
    /** The heel's elements for coordination, and the sizes per heel. */
    private final javax.swing.JTextField heelElements = new javax.swing.JTextField(10);

    private final javax.swing.JTextField heelGroup = new javax.swing.JTextField(4);
    /** Table 3.1's width fitting whose last girths the table shows. */
    private final JComboBox<String> fitting = new JComboBox<>(GradingViewModel.FITTINGS.toArray(new String[0]));

    private final JButton grade = new JButton("Grade");
    private final JLabel status = new JLabel(" ");
    private final FieldEdits edits = new FieldEdits(this::fieldsGood, this::commit);

    GradingTab(AppContext ctx) {
        super("Grading");
        this.ctx = ctx;
        FormGrid form = new FormGrid(3);
        JButton open = Buttons.of("Open outline...", "grading-open", KeyEvent.VK_O, this::openOutline);
        JButton heel = new JButton("Heel centre");
        heel.setMnemonic('H');
        heel.setToolTipText("Grade about the heel circle's centre (clears the origin)");
        heel.addActionListener(e -> {
            origin.setText("");
            refreshPlot();
        });
        pick.setMnemonic('P');
        pick.setToolTipText("Click the plot to set the fixed point of the grading");
        grade.setMnemonic('G');
        grade.setName("grading-grade");
        grade.addActionListener(e -> grade());
        JButton export = Buttons.of("Export files...", "grading-export", KeyEvent.VK_X, this::export);
        lengthStep.setToolTipText("mm per whole size; empty for the system's (Brazilian 6.66)");
        widthStep.setToolTipText("mm per whole size; empty for the system's (Brazilian 1.66)");
        origin.setToolTipText("X,Y in mm; empty for the heel circle's centre");
        halfSizes.setMnemonic('A');
        outlineName.setName(GradingViewModel.OUTLINE);
        origin.setName(GradingViewModel.ORIGIN);
        system.setName(GradingViewModel.SYSTEM);
        baseSize.setName(GradingViewModel.BASE_SIZE);
        sizes.setName(GradingViewModel.SIZES);
        halfSizes.setName("grading-half-sizes");
        lengthStep.setName(GradingViewModel.LENGTH_STEP);
        widthStep.setName(GradingViewModel.WIDTH_STEP);
        shrinkage.setName(GradingViewModel.SHRINKAGE);
        shrinkageMode.setName(GradingViewModel.SHRINKAGE_MODE);
        status.setName("grading-status");
        status.setForeground(ProblemMarks.PROBLEM);
        for (JTextField f : textFields()) {
            TextChanges.onChange(f, () -> edits.typed(f.getName()));
        }
        system.addActionListener(e -> edits.chosen(null));
        shrinkageMode.addActionListener(e -> edits.chosen(null));
        halfSizes.addActionListener(e -> edits.chosen(null));

        form.row("Outline:", 'U', open, outlineName);
        form.row("Origin X,Y:", 'I', origin, null);
        form.row("", (char) 0, pick, heel);
        form.row("System:", 'Y', system, null);
        form.row("Base size:", 'B', baseSize, null);
        form.row("Sizes A-B:", 'Z', sizes, null);
        form.row("", (char) 0, halfSizes, null);
        form.row("Length step (mm):", 'L', lengthStep, null);
        form.row("Width step (mm):", 'W', widthStep, null);
        form.row("Shrinkage:", 'S', shrinkage, null);
        form.row("Shrinkage mode:", 'M', shrinkageMode, null);
        fitting.setName("grading-fitting");
        fitting.setToolTipText("Width fitting A-H: the table shows the last girth of each size (thesis table 3.1,"
                + " French sizes 29-42, Brazilian 27-40)");
        fitting.addActionListener(e -> {
            vm.setFitting((String) fitting.getSelectedItem());
            vm.result().ifPresent(this::showResult);
        });
        form.row("Width fitting:", 'T', fitting, null);
        heelElements.setName("grading-heel-elements");
        heelElements.setToolTipText("Coordination: the outline's elements that form the heel (e.g. 1-4,18-20; 1 the"
                + " first element), graded as one heel per group of sizes; empty for none");
        heelGroup.setName("grading-heel-group");
        heelGroup.setToolTipText("Sizes per heel (the thesis: 3)");
        form.row("Heel elements:", 'N', heelElements, null);
        form.row("Heel group:", 'R', heelGroup, null);
        form.row("", (char) 0, grade, export);
        form.wide(status, 3);
        form.end();

        JTable table = new JTable(tableModel);
        table.setName("grading-table");
        table.setFillsViewportHeight(true);
        JSplitPane right = new JSplitPane(JSplitPane.VERTICAL_SPLIT, plot, new JScrollPane(table));
        right.setResizeWeight(0.75);
        panel.add(new JScrollPane(form.panel()), BorderLayout.WEST);
        panel.add(right, BorderLayout.CENTER);

        installPicking();
        ctx.model().addListener(e -> {
            if (MainViewModel.DOCUMENT.equals(e.getPropertyName())) {
                showJob(true);
            } else if (MainViewModel.JOB.equals(e.getPropertyName())
                    && !ctx.model().job().grading().equals(shown)) {
                // an undo, a redo: the fields take the job's settings
                showJob(false);
            }
        });
        showJob(true);
    }

    private JTextField[] textFields() {
        return new JTextField[] {origin, baseSize, sizes, lengthStep, widthStep, shrinkage};
    }

    /** The job's grading settings, or the empty tab when it has none; a new document shows no result. */
    private void showJob(boolean document) {
        edits.drop();
        if (document || ctx.model().job().grading().isEmpty()) {
            vm = new GradingViewModel();
        }
        vm.load(ctx.model().job());
        shown = ctx.model().job().grading();
        showFields();
        tableModel.setRowCount(0);
        vm.clearResult();
        refreshPlot();
        check();
    }

    /** The view model takes the fields, which are marked; true when every one is good. */
    private boolean fieldsGood() {
        pushFields();
        return check().isEmpty();
    }

    /**
     * The view model takes the fields and, when every field is good, the job takes the settings
     * (one undo step per field typed into; a value the grading refuses never reaches it).
     */
    private void commit(String field) {
        pushFields();
        if (!check().isEmpty()) {
            return;
        }
        GradingSettings s = vm.typedSettings().orElseThrow();
        shown = Optional.of(s);
        ctx.model().setJob(ctx.model().job().withGrading(s), field);
    }

    /** Marks the bad fields, says the first problem beside Grade and why Grade is disabled. */
    private java.util.Map<String, String> check() {
        java.util.Map<String, String> problems = vm.problems();
        for (JComponent f :
                new JComponent[] {origin, baseSize, sizes, lengthStep, widthStep, shrinkage, system, shrinkageMode}) {
            ProblemMarks.mark(f, problems.get(f.getName()), "Grading");
        }
        ProblemMarks.enable(
                grade,
                problems,
                "Grade the outline into every size of the range",
                GradingViewModel.OUTLINE,
                "Open a base outline first");
        say(ProblemMarks.first(problems));
        return problems;
    }

    /** The line under Grade; a long reason wraps within the form's width and stays whole in the tooltip. */
    private void say(String text) {
        ProblemMarks.say(status, text, 36, 190);
    }

    /** Clicks on the plot set the origin while "Pick on plot" is on. */
    private void installPicking() {
        plot.chartComponent().addMouseListener(new MouseAdapter() {
            @Override
            public void mouseClicked(MouseEvent e) {
                if (!pick.isSelected()) {
                    return;
                }
                vm.pickOrigin(plot.toPlotMm(e.getPoint()));
                origin.setText(vm.origin());
                pick.setSelected(false);
                tableModel.setRowCount(0);
                refreshPlot();
            }
        });
    }

    private void showFields() {
        edits.fill(this::fillFields);
    }

    private void fillFields() {
        outlineName.setText(
                vm.outlineFile().map(p -> p.getFileName().toString()).orElse("(none)"));
        origin.setText(vm.origin());
        system.setSelectedItem(vm.system());
        baseSize.setText(vm.baseSize());
        sizes.setText(vm.sizes());
        halfSizes.setSelected(vm.halfSizes());
        lengthStep.setText(vm.lengthStep());
        widthStep.setText(vm.widthStep());
        shrinkage.setText(vm.shrinkage());
        shrinkageMode.setSelectedItem(vm.shrinkageMode());
        heelElements.setText(vm.heelElements());
        heelGroup.setText(vm.heelGroup());
    }

    private void pushFields() {
        vm.setOrigin(origin.getText());
        vm.setSystem((SizeSystem) system.getSelectedItem());
        vm.setBaseSize(baseSize.getText());
        vm.setSizes(sizes.getText());
        vm.setHalfSizes(halfSizes.isSelected());
        vm.setLengthStep(lengthStep.getText());
        vm.setWidthStep(widthStep.getText());
        vm.setShrinkage(shrinkage.getText());
        vm.setShrinkageMode((ShrinkageMode) shrinkageMode.getSelectedItem());
        vm.setHeelElements(heelElements.getText());
        vm.setHeelGroup(heelGroup.getText());
    }

    private void openOutline() {
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.OUTLINE);
        vm.outlineFile().ifPresent(p -> fc.setCurrentDirectory(p.getParent().toFile()));
        if (fc.showOpenDialog(ctx.owner()) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        try {
            vm.openOutline(FileChoosers.chosen(fc));
        } catch (CamInputException | java.io.IOException e) {
            say(e.getMessage());
            return;
        }
        showFields();
        tableModel.setRowCount(0);
        refreshPlot();
        edits.chosen(null);
    }

    /**
     * Grades with the typed settings (the job's already, as each good field goes into it); a
     * grading the planner refuses is said beside Grade, and the status bar says "failed".
     */
    private void grade() {
        edits.flush();
        pushFields();
        if (!check().isEmpty()) {
            return;
        }
        GradingSettings s = vm.typedSettings().orElseThrow();
        GradingViewModel graded = vm;
        int generation = ctx.model().generation();
        say("grading");
        ctx.tasks()
                .start(
                        "Grading",
                        progress -> {
                            try {
                                return (Object) graded.grade(s);
                            } catch (CamInputException e) {
                                return e.getMessage();
                            }
                        },
                        r -> {
                            if (graded != vm || generation != ctx.model().generation()) {
                                return;
                            }
                            if (r instanceof GradingResult g) {
                                say(" ");
                                showResult(g);
                            } else {
                                ctx.tasks().failed("Grading");
                                say(String.valueOf(r));
                            }
                        });
    }

    private void showResult(GradingResult r) {
        vm.setResult(r);
        tableModel.setRowCount(0);
        for (List<String> row : vm.tableRows()) {
            tableModel.addRow(row.toArray());
        }
        refreshPlot();
    }

    private void export() {
        pushFields();
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.FOLDER);
        fc.setDialogTitle("Folder for the graded sizes");
        if (fc.showSaveDialog(ctx.owner()) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path dir = FileChoosers.chosen(fc);
        ctx.tasks()
                .start(
                        "Export grading",
                        progress -> vm.export(dir, progress),
                        (TaskOutcome o) -> Dialogs.info(
                                ctx.owner(),
                                "Export grading",
                                "Wrote " + o.files().size() + " files in " + dir));
    }

    private void refreshPlot() {
        plot.show(vm.scene());
    }
}
