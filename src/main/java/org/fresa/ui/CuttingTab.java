package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.event.KeyEvent;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.fresa.chart.PlotScene;
import org.fresa.cutting.CutProcess;
import org.fresa.cutting.CutSense;
import org.fresa.cutting.KerfCompensation;
import org.fresa.cutting.LeadShape;
import org.fresa.job.CuttingService;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.model.CamInputException;
import org.fresa.post.CuttingPost;
import org.fresa.setting.SettingRanges.Cutting;

/**
 * Sheet cutting: open a DXF, set kerf, process, leads, compensation and directions, cut, see the
 * plan (parts, holes, open chains, pierces, leads, order, rapids), the totals and the program.
 */
final class CuttingTab extends PlotTab {

    private final AppContext ctx;
    private CuttingViewModel vm = new CuttingViewModel();
    // the job's cutting settings the fields show: a job that holds others is shown afresh
    private Optional<CuttingSettings> shown = Optional.empty();
    private final WarningsPanel warnings = new WarningsPanel("cutting-warnings", 5);
    private final JTextArea program = new JTextArea();
    private final JTextArea totals = new JTextArea("No drawing cut yet.");
    private final JLabel file = new JLabel("(none)");
    private final JTextField kerf = new JTextField(6);
    private final JComboBox<CutProcess> process =
            new JComboBox<>(Cutting.PROCESS.values().toArray(new CutProcess[0]));
    private final JTextField leadIn = new JTextField(6);
    private final JTextField leadOut = new JTextField(6);
    private final JComboBox<LeadShape> lead =
            new JComboBox<>(Cutting.LEAD.values().toArray(new LeadShape[0]));
    private final JTextField overcut = new JTextField(6);
    private final JComboBox<KerfCompensation> compensation =
            new JComboBox<>(Cutting.COMPENSATION.values().toArray(new KerfCompensation[0]));
    private final JComboBox<CutSense> outerDir =
            new JComboBox<>(Cutting.OUTER_DIRECTION.values().toArray(new CutSense[0]));
    private final JComboBox<CutSense> holeDir =
            new JComboBox<>(Cutting.HOLE_DIRECTION.values().toArray(new CutSense[0]));
    private final JCheckBox avoid = new JCheckBox("Rapids around cut parts");
    private final JComboBox<CuttingPost> post =
            new JComboBox<>(Cutting.POST.values().toArray(new CuttingPost[0]));
    private final JCheckBox paper = new JCheckBox("Paper mode (2010)");
    private final JButton cut = new JButton("Cut");
    // the cut list: the order and starts of the last cut, which the planner edits
    private final javax.swing.table.DefaultTableModel orderRows =
            new javax.swing.table.DefaultTableModel(new Object[] {"#", "Contour", "Start (mm)"}, 0) {
                private static final long serialVersionUID = 1L;

                @Override
                public boolean isCellEditable(int row, int column) {
                    return false;
                }
            };
    private final javax.swing.JTable order = new javax.swing.JTable(orderRows);
    private final JTextField start = new JTextField(12);
    private final JButton setStart = new JButton("Set");
    private final JButton up = new JButton("Up");
    private final JButton down = new JButton("Down");
    private final JButton resetOrder = new JButton("Reset order");
    // the row to select once the cut after an edit of the list is shown
    private int selectAfterCut = -1;
    // the order the list shows was cut with: an edit waits until the list shows the job's order
    private org.fresa.cutting.CutOrderOverride listed;
    private final JLabel status = new JLabel(" ");
    private final FieldEdits edits = new FieldEdits(this::fieldsGood, this::commit);

    CuttingTab(AppContext ctx) {
        super("Cutting");
        this.ctx = ctx;
        FormGrid form = new FormGrid(2);
        JButton open = Buttons.of("Open DXF...", "cutting-open", KeyEvent.VK_O, this::choose);
        cut.setMnemonic('C');
        cut.setName("cutting-cut");
        cut.addActionListener(e -> run());
        kerf.setName(CuttingViewModel.KERF);
        leadIn.setName(CuttingViewModel.LEAD_IN);
        leadOut.setName(CuttingViewModel.LEAD_OUT);
        overcut.setName(CuttingViewModel.OVERCUT);
        file.setName(CuttingViewModel.DRAWING);
        status.setName("cutting-status");
        status.setForeground(ProblemMarks.PROBLEM);
        for (JTextField f : new JTextField[] {kerf, leadIn, leadOut, overcut}) {
            TextChanges.onChange(f, () -> edits.typed(f.getName()));
        }
        for (JComboBox<?> c : java.util.List.of(process, lead, compensation, outerDir, holeDir, post)) {
            c.addActionListener(e -> edits.chosen(null));
        }
        avoid.addActionListener(e -> edits.chosen(null));
        paper.addActionListener(e -> edits.chosen(null));
        kerf.setToolTipText("full kerf width; the path runs half of it off the part");
        compensation.setName("cutting-compensation");
        compensation.setToolTipText("software: offset path; controller: the drawn contour with G41/G42");
        outerDir.setToolTipText("process: the process's default (outer clockwise)");
        holeDir.setToolTipText("process: the opposite sense of the outer contours");
        avoid.setMnemonic('R');
        paper.setMnemonic('M');
        program.setEditable(false);
        program.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        program.setName("cutting-program");
        totals.setEditable(false);
        totals.setLineWrap(true);
        totals.setWrapStyleWord(true);
        totals.setOpaque(false);
        totals.setName("cutting-totals");
        totals.setColumns(18);

        buildOrderControls();
        form.row("Drawing:", (char) 0, open, null);
        form.row("", (char) 0, file, null);
        form.row("Kerf (mm):", 'K', kerf, null);
        form.row("Process:", 'P', process, null);
        form.row("Lead-in (mm):", 'I', leadIn, null);
        form.row("Lead-out (mm):", 'U', leadOut, null);
        form.row("Lead shape:", 'L', lead, null);
        form.row("Overcut (mm):", 'V', overcut, null);
        form.row("Compensation:", 'N', compensation, null);
        form.row("Outer sense:", 'E', outerDir, null);
        form.row("Hole sense:", 'H', holeDir, null);
        form.row("", (char) 0, avoid, null);
        form.row("Post:", 'S', post, null);
        form.row("", (char) 0, paper, null);
        form.row("", (char) 0, cut, null);
        form.wide(status, 2);
        form.wide(totals, 10);
        form.wide(orderPanel(), 10);
        form.end();

        JScrollPane text = new JScrollPane(program);
        text.setPreferredSize(new java.awt.Dimension(260, 200));
        warnings.onSelect(this::showWarning);
        // a contour not cut names itself and its reason under the mouse
        javax.swing.JComponent chart = plot.chartComponent();
        chart.addMouseMotionListener(new java.awt.event.MouseMotionAdapter() {
            @Override
            public void mouseMoved(java.awt.event.MouseEvent e) {
                org.fresa.geom.Vec2 at = plot.toPlotMm(e.getPoint());
                java.awt.Point aside = new java.awt.Point(e.getX() + 6, e.getY());
                double reach = plot.toPlotMm(aside).distance(at);
                chart.setToolTipText(vm.notCutAt(at, reach).orElse(null));
            }
        });
        // Shift+click: the cut nearest the click starts at the point of its path nearest the click
        chart.addMouseListener(new java.awt.event.MouseAdapter() {
            @Override
            public void mouseClicked(java.awt.event.MouseEvent e) {
                if (e.isShiftDown() && javax.swing.SwingUtilities.isLeftMouseButton(e)) {
                    pickStart(plot.toPlotMm(e.getPoint()));
                }
            }
        });
        JSplitPane plotAndWarnings = new JSplitPane(JSplitPane.VERTICAL_SPLIT, plot, warnings);
        plotAndWarnings.setResizeWeight(0.85);
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, plotAndWarnings, text);
        split.setResizeWeight(0.75);
        panel.add(new JScrollPane(form.panel()), BorderLayout.WEST);
        panel.add(split, BorderLayout.CENTER);

        ctx.model().addListener(e -> {
            if (MainViewModel.DOCUMENT.equals(e.getPropertyName())) {
                showJob(true);
            } else if (MainViewModel.JOB.equals(e.getPropertyName())
                    && !ctx.model().job().cutting().equals(shown)) {
                // an undo, a redo: the fields take the job's settings, a cut of the same drawing stays;
                // an order or start undone is cut again, so that the list shows what the job cuts
                org.fresa.cutting.CutOrderOverride was = vm.cutOrder();
                showJob(false);
                if (vm.result().isPresent() && !vm.cutOrder().equals(was)) {
                    run();
                }
            }
        });
        showJob(true);
    }

    /** The job's cutting settings, or the empty tab when it has none; a new document shows no result. */
    private void showJob(boolean document) {
        edits.drop();
        if (document || ctx.model().job().cutting().isEmpty()) {
            vm = new CuttingViewModel();
        }
        vm.load(ctx.model().job());
        shown = ctx.model().job().cutting();
        showFields();
        if (vm.result().isEmpty()) {
            plot.show(vm.scene());
            program.setText("");
            totals.setText("No drawing cut yet.");
            warnings.show(WarningList.none());
            showOrder();
        }
        check();
    }

    /** The view model takes the fields, which are marked; true when every one is good. */
    private boolean fieldsGood() {
        takeFields();
        return check().isEmpty();
    }

    /**
     * The view model takes the fields and, when every field is good, the job takes the settings
     * (one undo step per field typed into; a bad value never reaches the job).
     *
     * @return whether the job took them
     */
    private boolean commit(String field) {
        if (!fieldsGood()) {
            return false;
        }
        CuttingSettings s = vm.typedSettings().orElseThrow();
        shown = Optional.of(s);
        ctx.model().setJob(ctx.model().job().withCutting(s), field);
        return true;
    }

    /** Marks the bad fields, says the first problem beside Cut and why Cut is disabled. */
    private java.util.Map<String, String> check() {
        java.util.Map<String, String> problems = vm.problems();
        for (JTextField f : new JTextField[] {kerf, leadIn, leadOut, overcut}) {
            ProblemMarks.mark(f, problems.get(f.getName()), "Cutting");
        }
        ProblemMarks.enable(
                cut,
                problems,
                "Plan the cut and show its path, totals and program",
                CuttingViewModel.DRAWING,
                "Open a DXF drawing first");
        say(ProblemMarks.first(problems));
        return problems;
    }

    /** The line under Cut; a long reason wraps within the form's width and stays whole in the tooltip. */
    private void say(String text) {
        ProblemMarks.say(status, text, 36, 170);
    }

    private void showFields() {
        edits.fill(this::fillFields);
    }

    private void fillFields() {
        file.setText(vm.drawing().map(p -> p.getFileName().toString()).orElse("(none)"));
        kerf.setText(vm.kerfMm());
        process.setSelectedItem(vm.process());
        leadIn.setText(vm.leadInMm());
        leadOut.setText(vm.leadOutMm());
        lead.setSelectedItem(vm.lead());
        overcut.setText(vm.overcutMm());
        compensation.setSelectedItem(vm.compensation());
        outerDir.setSelectedItem(vm.outerDirection());
        holeDir.setSelectedItem(vm.holeDirection());
        avoid.setSelected(vm.avoidCutParts());
        post.setSelectedItem(vm.post());
        paper.setSelected(vm.paperMode());
    }

    private void takeFields() {
        vm.setKerfMm(kerf.getText());
        vm.setProcess((CutProcess) process.getSelectedItem());
        vm.setLeadInMm(leadIn.getText());
        vm.setLeadOutMm(leadOut.getText());
        vm.setLead((LeadShape) lead.getSelectedItem());
        vm.setOvercutMm(overcut.getText());
        vm.setCompensation((KerfCompensation) compensation.getSelectedItem());
        vm.setOuterDirection((CutSense) outerDir.getSelectedItem());
        vm.setHoleDirection((CutSense) holeDir.getSelectedItem());
        vm.setAvoidCutParts(avoid.isSelected());
        vm.setPost((CuttingPost) post.getSelectedItem());
        vm.setPaperMode(paper.isSelected());
    }

    private void choose() {
        JFileChooser ch = FileChoosers.chooser(FileChoosers.Kind.DXF);
        if (ch.showOpenDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION) {
            Path p = FileChoosers.chosen(ch);
            vm.setDrawing(p);
            file.setText(p.getFileName().toString());
            plot.show(vm.scene());
            program.setText("");
            totals.setText("No drawing cut yet.");
            warnings.show(WarningList.none());
            edits.chosen(null);
        }
    }

    /**
     * Cuts the drawing with the typed settings (the job's already, as each good field goes into
     * it); a drawing the cut refuses is said beside Cut, and the status bar says "failed".
     */
    void run() {
        edits.flush();
        takeFields();
        if (!check().isEmpty()) {
            return;
        }
        CuttingSettings s = vm.typedSettings().orElseThrow();
        CuttingViewModel cutting = vm;
        int generation = ctx.model().generation();
        say("cutting");
        ctx.tasks()
                .start(
                        "Cutting",
                        progress -> {
                            CuttingService.Result r;
                            try {
                                r = CuttingService.compute(s, progress);
                            } catch (CamInputException | java.io.IOException e) {
                                return new Shown(null, null, e.getMessage(), null, null);
                            }
                            progress.progress(-1, "preparing the plot and the program text");
                            CuttingViewModel.Said said = CuttingViewModel.saidOf(r);
                            return new Shown(
                                    r,
                                    CuttingViewModel.sceneOf(r),
                                    CuttingViewModel.totalsOf(r, said),
                                    TextDocuments.of(r.program()),
                                    said);
                        },
                        shown -> {
                            if (cutting != vm || generation != ctx.model().generation()) {
                                return;
                            }
                            if (shown.result() == null) {
                                ctx.tasks().failed("Cutting");
                                say(shown.totals());
                                return;
                            }
                            listed = s.cutOrder();
                            vm.setResult(shown.result(), shown.said());
                            // a program the check refuses is not written by a run: said beside Cut, as a refusal
                            say(vm.refusal().orElse(" "));
                            plot.show(shown.scene());
                            program.setDocument(shown.program());
                            program.setCaretPosition(0);
                            totals.setText(shown.totals());
                            warnings.show(vm.warnings());
                            showOrder();
                        });
    }

    // ------------------------------------------------------------------ the cut list

    private void buildOrderControls() {
        order.setName("cutting-order");
        order.setSelectionMode(javax.swing.ListSelectionModel.SINGLE_SELECTION);
        order.setFillsViewportHeight(true);
        order.getColumnModel().getColumn(0).setMaxWidth(32);
        order.getColumnModel().getColumn(1).setPreferredWidth(110);
        order.getColumnModel().getColumn(2).setPreferredWidth(140);
        order.setToolTipText("The cuts in order: Alt+Up and Alt+Down move the selected one; Shift+click in the plot"
                + " starts the nearest cut there; * marks a start of your own");
        // the header says what the table holds, as every table's
        order.getTableHeader().setToolTipText(order.getToolTipText());
        javax.swing.InputMap im = order.getInputMap(JComponent.WHEN_FOCUSED);
        im.put(javax.swing.KeyStroke.getKeyStroke("alt UP"), "cut-up");
        im.put(javax.swing.KeyStroke.getKeyStroke("alt DOWN"), "cut-down");
        order.getActionMap().put("cut-up", action(() -> move(-1)));
        order.getActionMap().put("cut-down", action(() -> move(1)));
        order.getSelectionModel().addListSelectionListener(e -> {
            if (!e.getValueIsAdjusting()) {
                showSelectedStart();
            }
        });
        start.setName("cutting-start");
        start.setToolTipText("Where the selected cut starts, x, y in mm: it moves to the nearest point of its path"
                + " (Enter to apply)");
        start.addActionListener(e -> typedStart());
        setStart.setName("cutting-start-set");
        setStart.setToolTipText("Start the selected cut at the point typed");
        setStart.addActionListener(e -> typedStart());
        up.setName("cutting-order-up");
        up.setToolTipText("Cut the selected contour one place earlier (Alt+Up)");
        up.addActionListener(e -> move(-1));
        down.setName("cutting-order-down");
        down.setToolTipText("Cut the selected contour one place later (Alt+Down)");
        down.addActionListener(e -> move(1));
        resetOrder.setName("cutting-order-reset");
        resetOrder.setMnemonic('T');
        resetOrder.setToolTipText("Back to the automatic order and start points");
        resetOrder.addActionListener(e -> {
            if (!vm.cutOrder().isEmpty()) {
                vm.resetOrder();
                orderEdited(order.getSelectedRow());
            }
        });
    }

    private static javax.swing.Action action(Runnable r) {
        return new javax.swing.AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                r.run();
            }
        };
    }

    private JPanel orderPanel() {
        JPanel p = new JPanel(new BorderLayout(2, 2));
        p.setBorder(BorderFactory.createTitledBorder("Cut order"));
        JScrollPane rows = new JScrollPane(order);
        rows.setPreferredSize(new java.awt.Dimension(280, 170));
        p.add(rows, BorderLayout.CENTER);
        JPanel below = new JPanel(new GridBagLayout());
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(1, 1, 1, 1);
        c.anchor = GridBagConstraints.WEST;
        JLabel l = new JLabel("Start:");
        l.setDisplayedMnemonic('A');
        l.setLabelFor(start);
        below.add(l, c);
        c.gridx = 1;
        c.weightx = 1;
        c.fill = GridBagConstraints.HORIZONTAL;
        below.add(start, c);
        c.gridx = 2;
        c.weightx = 0;
        c.fill = GridBagConstraints.NONE;
        below.add(setStart, c);
        JPanel buttons = new JPanel(new java.awt.FlowLayout(java.awt.FlowLayout.LEFT, 2, 0));
        buttons.add(up);
        buttons.add(down);
        buttons.add(resetOrder);
        c.gridx = 0;
        c.gridy = 1;
        c.gridwidth = 3;
        below.add(buttons, c);
        p.add(below, BorderLayout.SOUTH);
        return p;
    }

    /** The list shows the last cut's order and starts; the row asked for after an edit is selected. */
    private void showOrder() {
        orderRows.setRowCount(0);
        for (CuttingViewModel.CutRow r : vm.cutList()) {
            orderRows.addRow(new Object[] {r.number(), r.contour(), r.start() + (r.startAsked() ? " *" : "")});
        }
        boolean any = orderRows.getRowCount() > 0;
        int select = Math.min(selectAfterCut, orderRows.getRowCount() - 1);
        selectAfterCut = -1;
        if (select >= 0) {
            order.setRowSelectionInterval(select, select);
            order.scrollRectToVisible(order.getCellRect(select, 0, true));
        }
        for (JComponent c : new JComponent[] {order, start, setStart, up, down}) {
            c.setEnabled(any);
        }
        resetOrder.setEnabled(any && !vm.cutOrder().isEmpty());
        showSelectedStart();
    }

    private void showSelectedStart() {
        int i = order.getSelectedRow();
        List<CuttingViewModel.CutRow> rows = vm.cutList();
        start.setText(i >= 0 && i < rows.size() ? rows.get(i).start() : "");
    }

    /**
     * True when the list shows the cut of the job's order; else says so (an edit is being cut, or
     * its cut was cancelled) and the edit waits: it would start from a list the job has left.
     */
    private boolean listCurrent() {
        if (vm.result().isPresent() && !vm.cutOrder().equals(listed)) {
            say("The list is not yet cut with the last edit: wait for the cut, or press Cut.");
            return false;
        }
        return true;
    }

    /**
     * The row of the cut selected in a list that shows the job's order; none, with the reason said,
     * when the list waits for a cut or nothing is selected.
     */
    private java.util.OptionalInt selectedCut() {
        if (!listCurrent()) {
            return java.util.OptionalInt.empty();
        }
        int i = order.getSelectedRow();
        if (i < 0) {
            say("Select a cut in the list first.");
            return java.util.OptionalInt.empty();
        }
        return java.util.OptionalInt.of(i);
    }

    /** Alt+Up, Alt+Down, Up, Down: the selected cut one place earlier or later, one undo step. */
    private void move(int delta) {
        selectedCut().ifPresent(i -> answered(vm.moveCut(i, delta), i + delta));
    }

    private void typedStart() {
        java.util.OptionalInt i = selectedCut();
        if (i.isEmpty()) {
            return;
        }
        Optional<org.fresa.geom.Vec2> p = CuttingViewModel.parseStart(start.getText());
        if (p.isEmpty()) {
            say("Start: type x, y in mm, e.g. 12.5, 30");
            return;
        }
        answered(vm.setStart(i.getAsInt(), p.get()), i.getAsInt());
    }

    /** Shift+click in the plot: the nearest cut starts at the point of its path nearest the click. */
    private void pickStart(org.fresa.geom.Vec2 at) {
        if (!listCurrent()) {
            return;
        }
        int i = vm.cutNearest(at);
        if (i < 0) {
            return;
        }
        answered(vm.setStart(i, at), i);
    }

    /** The view model's answer to an edit: its refusal said, or the edit taken into the job. */
    private void answered(Optional<String> refused, int select) {
        refused.ifPresentOrElse(this::say, () -> orderEdited(select));
    }

    /** An edit of the list goes into the job (one undo step) and the drawing is cut again to show it. */
    private void orderEdited(int select) {
        edits.flush();
        if (!commit(null)) {
            return;
        }
        selectAfterCut = select;
        run();
    }

    /** A warning's place in the plot: the view centred on it, a ring around it. */
    private void showWarning(WarningList.Warning w) {
        if (w.place().isEmpty()) {
            return;
        }
        PlotScene scene = vm.scene();
        double size = scene.bounds().map(b -> Math.max(b.width(), b.height())).orElse(100.0);
        double view = Math.max(5, size / 6);
        plot.update(scene.withMarker("selected warning", w.place().get(), view / 30));
        plot.showPlace(w.place().get(), view);
    }

    /** A result with what the tab shows of it, prepared off the event thread; no result: totals says why. */
    private record Shown(
            CuttingService.Result result,
            org.fresa.chart.PlotScene scene,
            String totals,
            javax.swing.text.Document program,
            CuttingViewModel.Said said) {}
}
