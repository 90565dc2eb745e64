package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.FlowLayout;
import java.awt.GridLayout;
import java.awt.event.KeyEvent;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;
import javax.swing.BorderFactory;
import javax.swing.Box;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSlider;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.fresa.cell.RobotFiles;
import org.fresa.job.JobSettings;
import org.fresa.job.RobotTrajectoryService;
import org.fresa.model.CamInputException;

/**
 * The Position tab: where the table stands in front of the robot and the workpiece on the table,
 * Compute (the STEP-NC file of the STEP-NC tab with the robot of the Robot tab, in the
 * background), the cell in 3D, the results (joint values with their limits and the position
 * error per axis along the path, the summary) and a replay slider that moves the robot along
 * the path in the 3D view and the marker in the plots.
 */
final class PositionTab implements ModuleTab {

    private static final int[] RT_KEYS = {KeyEvent.VK_X, KeyEvent.VK_Y, KeyEvent.VK_Z, KeyEvent.VK_T};
    private static final int[] TP_KEYS = {
        KeyEvent.VK_A, KeyEvent.VK_B, KeyEvent.VK_E, KeyEvent.VK_I, KeyEvent.VK_G, KeyEvent.VK_N
    };

    private final AppContext ctx;
    private final RobotRunModel runs;
    private final PositionViewModel vm = new PositionViewModel();
    private final JPanel panel = new JPanel(new BorderLayout());
    private final JTextField[] robotTable = new JTextField[PositionViewModel.ROBOT_TABLE.length];
    private final JTextField[] tablePiece = new JTextField[PositionViewModel.TABLE_PIECE.length];
    private final JLabel messages = new JLabel(" ");
    private final JButton compute = new JButton("Compute");
    private final JButton placeAuto = new JButton("Place automatically");
    private final JSlider replay = new JSlider(0, 0, 0);
    private final JLabel pointLabel = new JLabel(" ");
    private final JTextArea summary = new JTextArea(8, 26);
    private final WarningsPanel said = new WarningsPanel("position-warnings", 5);
    private final CellView cell = new CellView(vm);
    private final JTabbedPane results = new JTabbedPane();
    private final javax.swing.table.DefaultTableModel errorAxesModel =
            new javax.swing.table.DefaultTableModel(PositionViewModel.ERROR_COLUMNS, 0) {
                private static final long serialVersionUID = 1L;

                @Override
                public boolean isCellEditable(int row, int column) {
                    return false;
                }
            };
    private final javax.swing.JTable errorAxes = new javax.swing.JTable(errorAxesModel);
    // the data of the last result's charts, the panels' charts (the event thread's: their markers
    // follow the replay) and those the drawing thread draws (its own, given each result's data)
    private transient TrajectoryCharts charts;
    private final transient TrajectoryCharts.Screen shownCharts = new TrajectoryCharts.Screen(false);
    private final transient TrajectoryCharts.Screen drawnCharts = new TrajectoryCharts.Screen(true);
    private double markedPoint = 1;
    private final OffThreadChartPanel jointsChart = chartPanel(() -> picture(true));
    private final OffThreadChartPanel errorChart = chartPanel(() -> picture(false));
    private boolean loading;
    private String drawnRobot = "";
    private final JLabel reach = new JLabel(" ");
    private final transient LiveReachability live =
            new LiveReachability(this::showLive, this::prepareLive, this::liveFailed);
    // the plot in view (null for the summary) and what each plot's zoom shows, as of the last
    // paint: the background thread draws the next answer's plot with them
    private transient volatile OffThreadChartPanel plotInView;
    private transient volatile java.util.List<Object> jointsView;
    private transient volatile java.util.List<Object> errorsView;
    // the time from a change to the 3D view painted with its reachability, and to the plot drawn (tests read them)
    private final java.util.List<Double> viewLatenciesMs = new java.util.ArrayList<>();
    private final java.util.List<Double> plotLatenciesMs = new java.util.ArrayList<>();
    private final java.util.List<Double> cpuMs = new java.util.ArrayList<>();
    private final java.util.List<double[]> splitsMs = new java.util.ArrayList<>();
    private final java.util.List<double[]> plotSplitsMs = new java.util.ArrayList<>();
    // the plots of the live answer shown, as they arrived on the event thread (System.nanoTime)
    private transient LiveReachability.Charted plotAsked;
    private long plotArrivedNanos;
    // when the last field was typed into and not yet asked about (System.nanoTime), or -1
    private long changedNanos = -1;
    private long plotAskedNanos = -1;
    private transient LiveReachability.Inputs shownInputs;

    PositionTab(AppContext ctx, RobotRunModel runs) {
        this.ctx = ctx;
        this.runs = runs;
        JPanel fields = new JPanel(new GridLayout(2, 1));
        fields.add(row(
                "Robot -> table (mm, deg):", "position-rt-", PositionViewModel.ROBOT_TABLE, robotTable, RT_KEYS, true));
        fields.add(row(
                "Table -> piece (mm, deg):",
                "position-tp-",
                PositionViewModel.TABLE_PIECE,
                tablePiece,
                TP_KEYS,
                false));
        compute.setName("position-compute");
        compute.setMnemonic(KeyEvent.VK_C);
        compute.addActionListener(e -> compute());
        placeAuto.setName("position-place-auto");
        placeAuto.setMnemonic(KeyEvent.VK_L);
        placeAuto.addActionListener(e -> placeAutomatically());
        placeAuto.setToolTipText(Tooltips.of("Position", "position-place-auto"));
        messages.setName("position-messages");
        messages.setForeground(new Color(180, 0, 0));
        JPanel actions = new JPanel(new FlowLayout(FlowLayout.LEFT));
        actions.add(compute);
        actions.add(placeAuto);
        actions.add(messages);
        reach.setName("position-reach");
        reach.setToolTipText("Which targets the robot reaches at these placements, worked out as you type"
                + " (one solution per target; Compute solves the trajectory with its relinks)");
        JPanel reachRow = new JPanel(new FlowLayout(FlowLayout.LEFT, 6, 0));
        reachRow.add(reach);
        JPanel top = new JPanel();
        top.setLayout(new BoxLayout(top, BoxLayout.Y_AXIS));
        top.add(fields);
        top.add(actions);
        top.add(reachRow);

        replay.setName("position-replay");
        replay.setEnabled(false);
        replay.addChangeListener(e -> {
            vm.select(replay.getValue());
            pointLabel.setText(vm.selectedText());
            markedPoint = vm.selected() + 1;
            shownCharts.mark(markedPoint);
            cell.repaint();
        });
        JLabel replayLabel = new JLabel("Replay point:");
        replayLabel.setDisplayedMnemonic(KeyEvent.VK_P);
        replayLabel.setLabelFor(replay);
        pointLabel.setName("position-point");
        JPanel replayPanel = new JPanel(new BorderLayout(6, 0));
        replayPanel.add(replayLabel, BorderLayout.WEST);
        replayPanel.add(replay, BorderLayout.CENTER);
        replayPanel.add(pointLabel, BorderLayout.SOUTH);

        summary.setEditable(false);
        summary.setName("position-summary");
        JLabel summaryLabel = new JLabel("Summary");
        summaryLabel.setDisplayedMnemonic(KeyEvent.VK_U);
        summaryLabel.setLabelFor(summary);
        JPanel summaryPanel = new JPanel(new BorderLayout());
        summaryPanel.add(summaryLabel, BorderLayout.NORTH);
        // the figures, and under them what fresa run says of the trajectory computed
        JPanel summaryAndSaid = new JPanel(new BorderLayout(0, 4));
        summaryAndSaid.add(new JScrollPane(summary), BorderLayout.CENTER);
        summaryAndSaid.add(said, BorderLayout.SOUTH);
        summaryPanel.add(summaryAndSaid, BorderLayout.CENTER);
        errorAxes.setName("position-error-axes");
        JScrollPane axesScroll = new JScrollPane(errorAxes);
        axesScroll.setPreferredSize(new java.awt.Dimension(300, 7 * errorAxes.getRowHeight() + 28));
        axesScroll.setBorder(BorderFactory.createTitledBorder("Error per axis (target - reached)"));
        summaryPanel.add(axesScroll, BorderLayout.SOUTH);
        results.setName("position-results");
        jointsChart.setName("position-joints-chart");
        errorChart.setName("position-error-chart");
        results.addTab("Joints", jointsChart);
        results.setMnemonicAt(0, KeyEvent.VK_J);
        results.addTab("Position error", errorChart);
        results.setMnemonicAt(1, KeyEvent.VK_O);
        results.addTab("Summary", summaryPanel);
        results.setMnemonicAt(2, KeyEvent.VK_M);
        results.setPreferredSize(new java.awt.Dimension(430, 420));
        jointsChart.onDrawn(this::plotDrawn);
        errorChart.onDrawn(this::plotDrawn);
        zoomable(jointsChart, true);
        zoomable(errorChart, false);
        results.addChangeListener(
                e -> plotInView = results.getSelectedComponent() instanceof OffThreadChartPanel p ? p : null);
        plotInView = jointsChart;

        JSplitPane views = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, cell, results);
        views.setResizeWeight(0.6);
        views.setContinuousLayout(true);
        JPanel centre = new JPanel(new BorderLayout(4, 4));
        centre.add(views, BorderLayout.CENTER);
        centre.add(replayPanel, BorderLayout.SOUTH);

        panel.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        panel.add(top, BorderLayout.NORTH);
        panel.add(centre, BorderLayout.CENTER);
        ctx.model().addListener(e -> {
            if (MainViewModel.DOCUMENT.equals(e.getPropertyName())) {
                documentReplaced();
            } else if (MainViewModel.JOB.equals(e.getPropertyName())) {
                ctx.model().job().robot().ifPresent(this::load);
            }
        });
        panel.addHierarchyListener(e -> {
            if ((e.getChangeFlags() & java.awt.event.HierarchyEvent.SHOWING_CHANGED) != 0
                    && panel.isShowing()
                    && vm.problems().isEmpty()) {
                requestLive();
            }
        });
        ctx.model().job().robot().ifPresent(this::load);
        showResult();
    }

    private JPanel row(String title, String prefix, String[] names, JTextField[] out, int[] keys, boolean robot) {
        JPanel p = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 2));
        JLabel t = new JLabel(title);
        t.setPreferredSize(
                new java.awt.Dimension(Math.max(190, t.getPreferredSize().width), t.getPreferredSize().height));
        p.add(t);
        for (int i = 0; i < names.length; i++) {
            int index = i;
            JTextField f = new JTextField(robot ? vm.robotTable(i) : vm.tablePiece(i), 6);
            f.setName(prefix + names[i]);
            JLabel l = new JLabel(names[i]);
            l.setDisplayedMnemonic(keys[i]);
            l.setLabelFor(f);
            l.setToolTipText(title + " " + names[i] + " (Alt+" + KeyEvent.getKeyText(keys[i]) + ")");
            TextChanges.onChange(f, () -> {
                changedNanos = System.nanoTime();
                if (robot) {
                    vm.setRobotTable(index, f.getText());
                } else {
                    vm.setTablePiece(index, f.getText());
                }
                validateFields(true, f.getName());
            });
            out[i] = f;
            p.add(l);
            p.add(f);
            p.add(Box.createHorizontalStrut(6));
        }
        return p;
    }

    @Override
    public String title() {
        return "Position";
    }

    @Override
    public JComponent component() {
        return panel;
    }

    private void load(JobSettings.RobotSettings r) {
        if (loading) {
            return;
        }
        loading = true;
        try {
            String key = robotKey(r.robot());
            if (!key.equals(drawnRobot)) {
                try {
                    vm.setRobot(RobotFiles.load(r.robot()));
                    drawnRobot = key;
                } catch (CamInputException ex) {
                    // the Robot tab reports a robot it cannot read; the view keeps the last one
                }
            }
            vm.load(r);
            for (int i = 0; i < robotTable.length; i++) {
                setIfDifferent(robotTable[i], vm.robotTable(i));
            }
            for (int i = 0; i < tablePiece.length; i++) {
                setIfDifferent(tablePiece[i], vm.tablePiece(i));
            }
        } finally {
            loading = false;
        }
        // the fields show the job's values: nothing to write back
        validateFields(false);
    }

    /** New or Open: the new job's placements (or none), no trajectory. */
    private void documentReplaced() {
        live.forget();
        vm.clearResult();
        charts = null;
        jointsChart.setChart(null);
        errorChart.setChart(null);
        drawnRobot = "";
        JobSettings.RobotSettings r = ctx.model().job().robot().orElse(JobSettings.RobotSettings.DEFAULTS);
        // the fields take the new job's values without writing them into it
        boolean was = loading;
        loading = false;
        load(r);
        loading = was;
        showResult();
    }

    /** A built-in name, or a file with the time it was written (a file saved again is read again). */
    private static String robotKey(String nameOrFile) {
        try {
            Path p = Path.of(nameOrFile);
            return java.nio.file.Files.isRegularFile(p)
                    ? nameOrFile + "@" + java.nio.file.Files.getLastModifiedTime(p)
                    : nameOrFile;
        } catch (java.io.IOException | java.nio.file.InvalidPathException e) {
            return nameOrFile;
        }
    }

    private static void setIfDifferent(JTextField f, String text) {
        if (!f.getText().trim().equals(text)) {
            f.setText(text);
        }
    }

    /** Shows the first problem, marks the bad fields, and writes good placements into the job. */
    private boolean validateFields() {
        return validateFields(true, null);
    }

    private boolean validateFields(boolean write) {
        return validateFields(write, null);
    }

    /** @param typed the field typed into (its keystrokes are one edit), or null */
    private boolean validateFields(boolean write, String typed) {
        Map<String, String> problems = vm.problems();
        mark(robotTable, "position-rt-", problems);
        mark(tablePiece, "position-tp-", problems);
        messages.setText(
                problems.isEmpty()
                        ? " "
                        : problems.size() == 1
                                ? problems.values().iterator().next()
                                : problems.values().iterator().next() + " (and " + (problems.size() - 1) + " more)");
        if (problems.isEmpty()) {
            // asked before the job takes the placements: the other tabs' answers to the new job run
            // on the event thread while the worker solves (the inputs are the same, the job's
            // STEP-NC file and robot with the fields' placements; asked again below in case not)
            requestLive();
        }
        if (problems.isEmpty() && !loading && write) {
            loading = true;
            try {
                ctx.model().setJob(vm.applyTo(ctx.model().job()), typed);
            } finally {
                loading = false;
            }
        }
        compute.setEnabled(problems.isEmpty());
        placeAuto.setEnabled(problems.isEmpty());
        if (problems.isEmpty()) {
            requestLive();
        }
        changedNanos = -1;
        if (vm.result().isEmpty()) {
            // before any answer the view draws the table where the fields put it; after, the answer's
            cell.repaint();
        }
        return problems.isEmpty();
    }

    /** The live reachability's inputs now: the job's STEP-NC file, robot and tool, the fields' placements. */
    private java.util.Optional<LiveReachability.Inputs> liveInputs() {
        var stepnc = ctx.model().job().stepnc();
        if (stepnc.isEmpty() || !vm.problems().isEmpty()) {
            return java.util.Optional.empty();
        }
        JobSettings.RobotSettings r = ctx.model()
                .job()
                .robot()
                .orElse(new JobSettings.RobotSettings(
                        "irb140",
                        org.fresa.model.Placement.ORIGIN,
                        org.fresa.model.Placement.ORIGIN,
                        JobSettings.RobotSettings.DEFAULT_FORMATS));
        return java.util.Optional.of(new LiveReachability.Inputs(
                stepnc.get().file(),
                stepnc.get().choices(),
                r.robot(),
                new org.fresa.cell.RobotTools.Choice(r.spindle(), r.toolLengthMm()),
                vm.robotTablePlacement(),
                vm.tablePiecePlacement(),
                r.formats()));
    }

    /** Asks which targets are reached at the placements shown (worked out in the background). */
    private void requestLive() {
        // only for the tab on screen: reading and planning the file takes a core for a second or
        // more, which a job opened in another tab should not compete with; the tab asks when shown
        if (!panel.isShowing()) {
            return;
        }
        var in = liveInputs();
        if (in.isEmpty()) {
            if (ctx.model().job().stepnc().isEmpty()) {
                reach.setText("Open a STEP-NC file: the targets' reach is then shown as you type.");
            }
            return;
        }
        live.request(in.get(), changedNanos >= 0 ? changedNanos : System.nanoTime());
    }

    /** A live answer: the 3D view, the plots, the summary and the out-of-reach line show it. */
    private void showLive(LiveReachability.Answer a) {
        long shown = System.nanoTime();
        long cpu0 = LiveReachability.cpuNanos();
        vm.setLive(a.solved(), a.scene(), a.spindle(), a.errorRows());
        shownInputs = a.inputs();
        reach.setForeground(a.solved().result().unreachable() > 0 ? CellView.UNREACHABLE : CellView.OK);
        reach.setText(vm.reachLine());
        showResult();
        long modelled = System.nanoTime();
        // painted now, so that the time measured is until the view shows the new reach (the repaint
        // showResult queued then copies the image this paint leaves)
        cell.paintImmediately(0, 0, cell.getWidth(), cell.getHeight());
        long painted = System.nanoTime();
        viewLatenciesMs.add((painted - a.askedNanos()) / 1e6);
        double edtCpuMs = cpu0 < 0 ? Double.NaN : (LiveReachability.cpuNanos() - cpu0) / 1e6;
        double workerCpuMs = a.cpuNanos() < 0 ? Double.NaN : a.cpuNanos() / 1e6;
        cpuMs.add(workerCpuMs + edtCpuMs);
        LiveReachability.Phases p = a.phases();
        splitsMs.add(new double[] {
            (p.asked() - p.changed()) / 1e6,
            (p.started() - p.asked()) / 1e6,
            (p.solved() - p.started()) / 1e6,
            (p.scened() - p.solved()) / 1e6,
            (shown - p.posted()) / 1e6,
            (modelled - shown) / 1e6,
            (painted - modelled) / 1e6,
            workerCpuMs,
            edtCpuMs
        });
    }

    /**
     * Runs on the background thread with the plots' data of a live answer just handed to the event
     * thread: the plot in view is drawn now, while the event thread paints the 3D view, and its
     * image is shown with the data.
     */
    private void prepareLive(LiveReachability.Charted c, java.util.function.BooleanSupplier stale) {
        OffThreadChartPanel panel = plotInView;
        java.util.List<Object> view = panel == jointsChart ? jointsView : errorsView;
        // a plot made stale by a newer change is not shown: the newer one follows, and the stale
        // one shown would only be drawn again at the panel's paint, ahead of it on the drawing thread
        if (panel == null || view == null) {
            javax.swing.SwingUtilities.invokeLater(() -> {
                if (!stale.getAsBoolean()) {
                    showLiveCharts(c, null, null);
                }
            });
            return;
        }
        // the answer shown replays its first point
        OffThreadChartPanel.Picture p = pictureOf(c.charts(), panel == jointsChart, 1, view);
        panel.prepare(p, stale, d -> {
            if (!stale.getAsBoolean()) {
                showLiveCharts(c, panel, d);
            }
        });
    }

    /**
     * The plots of the live answer shown, made after it; the image of the plot in view, drawn
     * ahead (or null), is copied to the screen at once when it shows what the panel shows now.
     */
    private void showLiveCharts(
            LiveReachability.Charted c, OffThreadChartPanel panel, OffThreadChartPanel.Prepared drawn) {
        if (!c.inputs().equals(shownInputs)) {
            return;
        }
        plotArrivedNanos = System.nanoTime();
        showCharts(c.charts());
        plotAskedNanos = c.changedNanos();
        plotAsked = c;
        if (drawn == null || panel != results.getSelectedComponent()) {
            return;
        }
        panel.install(drawn);
        if (panel.isUpToDate()) {
            panel.paintImmediately(0, 0, panel.getWidth(), panel.getHeight());
            long shown = System.nanoTime();
            plotLatenciesMs.add((shown - c.changedNanos()) / 1e6);
            plotAskedNanos = -1;
            OffThreadChartPanel.Drawn d = panel.lastDrawn();
            plotSplitsMs.add(new double[] {
                (c.postedNanos() - c.changedNanos()) / 1e6,
                (c.madeNanos() - c.postedNanos()) / 1e6,
                (d.started() - c.madeNanos()) / 1e6,
                (d.built() - d.started()) / 1e6,
                (d.drawn() - d.built()) / 1e6,
                (plotArrivedNanos - d.drawn()) / 1e6,
                (shown - plotArrivedNanos) / 1e6,
                c.cpuNanos() / 1e6,
                d.buildCpuNanos() / 1e6,
                d.drawCpuNanos() / 1e6
            });
        }
    }

    private void liveFailed(String message) {
        reach.setForeground(CellView.UNREACHABLE);
        reach.setText("Reach not known: " + message);
    }

    /** A plot image arrived: the first one up to date after a live answer ends its measurement. */
    private void plotDrawn() {
        OffThreadChartPanel shown = results.getSelectedComponent() == jointsChart
                ? jointsChart
                : results.getSelectedComponent() == errorChart ? errorChart : null;
        if (plotAskedNanos >= 0 && shown != null && shown.isUpToDate()) {
            plotLatenciesMs.add((System.nanoTime() - plotAskedNanos) / 1e6);
            plotAskedNanos = -1;
            OffThreadChartPanel.Drawn d = shown.lastDrawn();
            LiveReachability.Charted c = plotAsked;
            if (d != null && c != null) {
                // drawn at the panel's paint after the data arrived (no image drawn ahead)
                plotSplitsMs.add(new double[] {
                    (c.postedNanos() - c.changedNanos()) / 1e6,
                    (c.madeNanos() - c.postedNanos()) / 1e6,
                    (d.started() - c.madeNanos()) / 1e6,
                    (d.built() - d.started()) / 1e6,
                    (d.drawn() - d.built()) / 1e6,
                    (d.shown() - d.drawn()) / 1e6,
                    0,
                    c.cpuNanos() / 1e6,
                    d.buildCpuNanos() / 1e6,
                    d.drawCpuNanos() / 1e6
                });
            }
        }
    }

    /** Whether the live answer shown is that of the fields and job as they are now. */
    boolean showsLiveAnswerOfFields() {
        return shownInputs != null && liveInputs().equals(java.util.Optional.of(shownInputs));
    }

    /** Whether the plot on screen shows the last answer (tests wait for it before a screenshot). */
    boolean plotUpToDate() {
        return !(results.getSelectedComponent() instanceof OffThreadChartPanel p) || p.isUpToDate();
    }

    /** The scene the 3D view draws now. */
    CellScene scene() {
        return cell.scene();
    }

    /** The times (ms) from each field change to the 3D view painted with its reachability. */
    java.util.List<Double> viewLatenciesMs() {
        return java.util.List.copyOf(viewLatenciesMs);
    }

    /**
     * The CPU time (ms) each answer shown took: the background thread's (placing, solving, the scene;
     * its charts are made after it) and the event thread's (showing and painting it), without the
     * waits for a core.
     */
    java.util.List<Double> cpuMs() {
        return java.util.List.copyOf(cpuMs);
    }

    /**
     * Where the time of each answer shown went (ms): the event thread's handling of the change
     * before asking, the wait for the worker, solving the targets, the scene and table rows, the
     * wait for the event thread, showing the answer (model, labels, table) and painting the 3D view;
     * then the CPU time of the worker's part and of the event thread's.
     */
    java.util.List<double[]> splitsMs() {
        return java.util.List.copyOf(splitsMs);
    }

    /** The names of {@link #splitsMs()}'s figures, in order. */
    static final java.util.List<String> SPLITS =
            java.util.List.of("fields", "queue", "reach", "scene", "to-edt", "show", "paint", "worker-cpu", "edt-cpu");

    /**
     * Where the time of each plot shown after a live answer went (ms): the answer itself (reach and
     * scene, as for the 3D view), the plots' data on the worker, the wait for the drawing thread,
     * building the chart, drawing it, the wait for the event thread (it paints the 3D view
     * meanwhile), showing the data and copying the image to the screen; then the CPU time of the
     * plots' data, of the chart's building and of its drawing.
     */
    java.util.List<double[]> plotSplitsMs() {
        return java.util.List.copyOf(plotSplitsMs);
    }

    /** The names of {@link #plotSplitsMs()}'s figures, in order. */
    static final java.util.List<String> PLOT_SPLITS = java.util.List.of(
            "answer", "data", "to-draw", "build", "draw", "to-edt", "show", "data-cpu", "build-cpu", "draw-cpu");

    /** The times (ms) from each field change to the plot on screen drawn with its reachability. */
    java.util.List<Double> plotLatenciesMs() {
        return java.util.List.copyOf(plotLatenciesMs);
    }

    private static void mark(JTextField[] fs, String prefix, Map<String, String> problems) {
        for (JTextField f : fs) {
            String key = (prefix.contains("rt") ? "robot-table." : "table-piece.")
                    + f.getName().substring(prefix.length());
            String p = problems.get(key);
            f.setBackground(p == null ? Color.WHITE : new Color(255, 220, 220));
            f.setToolTipText(p != null ? p : Tooltips.of("Position", f.getName()));
        }
    }

    /**
     * The job's STEP-NC settings, for a computation of the cell ({@code title}) once the placement
     * fields are in the job; empty when a field is wrong (marked) or no STEP-NC file is open (said).
     * The cell is only previewed: the fields change the job's placements, never what the job runs.
     */
    private Optional<JobSettings.StepNcSettings> stepNcPlacedByFields(String title) {
        if (!validateFields()) {
            return Optional.empty();
        }
        var stepnc = ctx.model().job().stepnc();
        if (stepnc.isEmpty()) {
            Dialogs.error(ctx.owner(), title, "No STEP-NC file: open one in the STEP-NC tab first.");
            return Optional.empty();
        }
        ctx.model().setJob(vm.applyTo(ctx.model().job()));
        return stepnc;
    }

    /** Starts the computation in the background (also used by the GUI test). */
    void compute() {
        var stepnc = stepNcPlacedByFields("Compute");
        if (stepnc.isEmpty()) {
            return;
        }
        Path file = stepnc.get().file();
        JobSettings.RobotSettings r = ctx.model().job().robot().orElseThrow();
        int generation = ctx.model().generation();
        java.util.List<String> formats = r.formats();
        // Compute answers for these fields: a live answer still on its way would only hide it
        var asked = liveInputs();
        asked.ifPresent(live::answeredBy);
        ctx.tasks()
                .start(
                        "Computing the trajectory on " + r.robot(),
                        progress -> {
                            PositionViewModel.Planned planned = PositionViewModel.plan(
                                    file,
                                    r.robot(),
                                    new org.fresa.cell.RobotTools.Choice(r.spindle(), r.toolLengthMm()),
                                    stepnc.get().choices(),
                                    progress);
                            org.fresa.model.Placement robotTable = r.robotTable();
                            String placed = "";
                            if (r.placing() == org.fresa.cell.TablePlacing.AUTO) {
                                // a job that searches its placement is solved where fresa run solves it,
                                // on the toolpath just planned (as fresa run's search plans it)
                                if (planned.planning().planned() == 0) {
                                    throw new org.fresa.model.CamInputException(
                                            file.toString(), "no workingstep could be planned: nothing to place");
                                }
                                org.fresa.job.AutoPlacement.Outcome a = org.fresa.job.AutoPlacement.search(
                                        planned.toolpath(),
                                        planned.robot(),
                                        r.tablePiece(),
                                        planned.tcpByLabel(),
                                        planned.names(),
                                        progress);
                                if (!a.found()) {
                                    return Charted.refused(
                                            a.sentence(),
                                            org.fresa.job.RobotService.placementRefused(planned.planning(), a));
                                }
                                robotTable = a.robotTable();
                                placed = a.sentence();
                            }
                            RobotTrajectoryService.Solved solved = RobotTrajectoryService.solve(
                                    planned.request(robotTable, r.tablePiece(), formats), progress);
                            progress.progress(-1, "preparing the plots");
                            return new Charted(
                                    solved,
                                    TrajectoryCharts.of(solved),
                                    PositionViewModel.sceneOf(solved, 0, java.util.Optional.of(planned.spindle())),
                                    planned.spindle(),
                                    planned.planning(),
                                    placed,
                                    java.util.List.of());
                        },
                        charted -> {
                            if (generation != ctx.model().generation()) {
                                return;
                            }
                            if (charted.solved() == null) {
                                // no placement reaches every target: fresa run writes no trajectory either
                                vm.clearResult();
                                vm.setSaid(charted.refusal());
                                // and no programs: the Output tab shows none of an earlier Compute
                                runs.clear();
                                reach.setForeground(CellView.UNREACHABLE);
                                reach.setText(charted.placed());
                                showResult();
                                return;
                            }
                            RobotTrajectoryService.Solved solved = charted.solved();
                            String name = file.getFileName().toString().replaceFirst("\\.[^.]*$", "");
                            if (!live.lastAsked().equals(asked)) {
                                // the fields changed while it ran: the live view of the new ones stays
                                runs.set(new RobotRunModel.Run(solved, name, charted.planning()));
                                return;
                            }
                            vm.setResult(solved, charted.scene(), charted.spindle());
                            vm.setSaid(org.fresa.job.RobotService.said(charted.planning(), solved));
                            reach.setForeground(solved.result().unreachable() > 0 ? CellView.UNREACHABLE : CellView.OK);
                            // the Summary, not in view after Compute, lists what the run says
                            int n = vm.said().size();
                            reach.setText((charted.placed().isEmpty() ? "" : charted.placed() + ". ")
                                    + vm.reachLine()
                                    + (n == 0
                                            ? ""
                                            : " " + n + (n == 1 ? " warning" : " warnings") + " under Summary."));
                            runs.set(new RobotRunModel.Run(solved, name, charted.planning()));
                            showCharts(charted.charts());
                            showResult();
                        });
    }

    /**
     * Searches, in the background, the robot -> table placement that reaches every target of the
     * part with the largest joint-limit margin ({@code fresa robot --place auto}) and puts it into
     * the job's placement fields; says which workingsteps are out of reach when there is none.
     */
    void placeAutomatically() {
        var stepnc = stepNcPlacedByFields("Place automatically");
        if (stepnc.isEmpty()) {
            return;
        }
        Path file = stepnc.get().file();
        JobSettings.RobotSettings r = ctx.model().job().robot().orElseThrow();
        int generation = ctx.model().generation();
        ctx.tasks()
                .start(
                        "Searching the table placement for " + r.robot(),
                        progress -> org.fresa.job.AutoPlacement.search(
                                file,
                                stepnc.get().choices(),
                                r.robot(),
                                r.tablePiece(),
                                new org.fresa.cell.RobotTools.Choice(r.spindle(), r.toolLengthMm()),
                                progress),
                        outcome -> {
                            if (generation != ctx.model().generation()) {
                                return;
                            }
                            if (outcome.found()) {
                                // the fields follow the job (its listener loads them)
                                ctx.model()
                                        .setJob(PositionViewModel.withRobotTable(
                                                ctx.model().job(), outcome.robotTable()));
                                messages.setText(" ");
                                summary.setText(outcome.sentence());
                            } else {
                                Dialogs.info(ctx.owner(), "Place automatically", outcome.sentence());
                            }
                        });
    }

    /** A solved trajectory with its charts, made off the event thread. */
    private record Charted(
            RobotTrajectoryService.Solved solved,
            TrajectoryCharts charts,
            CellScene scene,
            org.fresa.geom.Transform3 spindle,
            org.fresa.job.RobotService.Planning planning,
            String placed,
            java.util.List<String> refusal) {

        /** No trajectory: the placement search (the job's place auto) found no placement reaching every target. */
        static Charted refused(String why, java.util.List<String> said) {
            return new Charted(null, null, null, null, null, why, said);
        }
    }

    private static OffThreadChartPanel chartPanel(java.util.function.Supplier<OffThreadChartPanel.Picture> picture) {
        OffThreadChartPanel p = new OffThreadChartPanel(null, picture);
        p.setPlaceholder("Press Compute: the plots of the trajectory appear here.");
        return p;
    }

    /** The joints (or error) chart as it is shown now: the last result with the replayed point, as zoomed. */
    private OffThreadChartPanel.Picture picture(boolean joints) {
        TrajectoryCharts c = charts;
        if (c == null) {
            return null;
        }
        java.util.List<Object> view = TrajectoryCharts.Screen.view((joints ? jointsChart : errorChart).getChart());
        if (joints) {
            jointsView = view;
        } else {
            errorsView = view;
        }
        return pictureOf(c, joints, markedPoint, view);
    }

    /** The joints (or error) chart of c with the point marked (from 1), its axes showing the view. */
    private OffThreadChartPanel.Picture pictureOf(
            TrajectoryCharts c, boolean joints, double point, java.util.List<Object> view) {
        java.util.List<Object> key = java.util.List.of(c, joints, point, view);
        // built on the drawing thread, the only one that touches drawnCharts
        return new OffThreadChartPanel.Picture(key, () -> {
            org.jfree.chart.JFreeChart chart = joints ? drawnCharts.joints(c, point) : drawnCharts.errors(c, point);
            TrajectoryCharts.Screen.show(chart, view);
            return chart;
        });
    }

    /**
     * Zoom with the mouse wheel or a drag, back to the whole trajectory with Home (a click in the
     * plot gives it the keyboard).
     */
    private void zoomable(OffThreadChartPanel p, boolean joints) {
        p.setMouseWheelEnabled(true);
        p.setFocusable(true);
        p.setToolTipText("wheel: zoom, drag: zoom to the box, Home: the whole trajectory again");
        p.addMouseListener(new java.awt.event.MouseAdapter() {
            @Override
            public void mousePressed(java.awt.event.MouseEvent e) {
                p.requestFocusInWindow();
            }
        });
        p.getInputMap(JComponent.WHEN_FOCUSED).put(javax.swing.KeyStroke.getKeyStroke("HOME"), "unzoom");
        p.getActionMap().put("unzoom", new javax.swing.AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                shownCharts.unzoom(joints);
            }
        });
    }

    /**
     * The two plots of the result (joints with limits, error per axis), with the replayed point
     * marked: the panels keep their charts, which take the new data in one change each.
     */
    private void showCharts(TrajectoryCharts c) {
        charts = c;
        markedPoint = vm.selected() + 1;
        var joints = shownCharts.joints(c, markedPoint);
        var errors = shownCharts.errors(c, markedPoint);
        if (jointsChart.getChart() != joints) {
            jointsChart.setChart(joints);
        }
        if (errorChart.getChart() != errors) {
            errorChart.setChart(errors);
        }
    }

    private void showResult() {
        summary.setText(String.join("\n", vm.summary()));
        summary.setCaretPosition(0);
        said.show(vm.said());
        errorAxesModel.setRowCount(0);
        for (String[] row : vm.errorRows()) {
            errorAxesModel.addRow(row);
        }
        replay.setMaximum(Math.max(0, vm.pointCount() - 1));
        replay.setValue(0);
        replay.setEnabled(vm.pointCount() > 0);
        pointLabel.setText(vm.pointCount() > 0 ? vm.selectedText() : "No trajectory yet.");
        cell.repaint();
    }
}
