package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.datatransfer.DataFlavor;
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import javax.swing.BorderFactory;
import javax.swing.DefaultComboBoxModel;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSlider;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.JTree;
import javax.swing.Timer;
import javax.swing.TransferHandler;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import org.fresa.job.JobSettings;
import org.fresa.job.ToolpathService;
import org.fresa.stepnc.StepNcProgram;
import org.fresa.toolpath.ToolpathPlanner;

/**
 * The STEP-NC tab: open a Part 21 file (button or drag and drop), browse project > workplans >
 * workingsteps, read the selected workingstep's data with units, see the block and the feature
 * with the workingstep's toolpath over it, one layer or all, replayed with a slider (arrow keys,
 * Page Up/Down, Home/End) or the Play button, and the cycle time. Reading and planning run in the
 * background; all state lives in {@link StepNcViewModel}.
 */
final class StepNcTab extends PlotTab {

    private final AppContext ctx;
    private StepNcViewModel vm = new StepNcViewModel();
    private final JLabel fileLabel = new JLabel("No file read. Open a STEP-NC file or drop one here.");
    private final JTree tree = new JTree(new DefaultTreeModel(new DefaultMutableTreeNode("No file")));
    private final JTextArea details = new JTextArea(14, 40);
    private final WarningsPanel problems = new WarningsPanel("stepnc-problems", 4);
    private final JComboBox<String> layers = new JComboBox<>();
    private final JComboBox<String> paths = new JComboBox<>();
    private final JSlider replay = new JSlider(0, StepNcViewModel.REPLAY_STEPS, StepNcViewModel.REPLAY_STEPS);
    private final JButton play = new JButton("Play");
    private final JLabel replayText = new JLabel(" ");
    private final JLabel cycleText = new JLabel(" ");
    private final JLabel legend = new JLabel(" ");
    private final Timer player = new Timer(40, e -> step());
    // set while the controls are filled from the view model, so their listeners do not echo back
    private boolean updating;
    // the file shown, and the last one asked for (a failed read is not retried on every job change)
    private Path loadedFile;
    // the path conventions the shown file was planned with
    private org.fresa.toolpath.PathConvention loadedPaths;
    private Path requestedFile;
    // the plot of the state a read leaves the tab in, drawn with the read: shown once, then dropped
    private org.fresa.chart.PlotScene preparedPlot;
    private List<String> preparedDetails;

    StepNcTab(AppContext ctx) {
        super("STEP-NC");
        this.ctx = ctx;
        JButton open = new JButton("Open STEP-NC file...");
        open.setMnemonic(KeyEvent.VK_O);
        open.setName("stepnc-open");
        open.addActionListener(e -> choose());
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(open);
        JLabel pathsLabel = new JLabel("Paths:");
        pathsLabel.setDisplayedMnemonic(KeyEvent.VK_A);
        pathsLabel.setLabelFor(paths);
        for (org.fresa.toolpath.PathConvention c : StepNcViewModel.PATHS) {
            paths.addItem(StepNcViewModel.pathsLabel(c));
        }
        paths.setName("stepnc-paths");
        paths.setToolTipText("Fresa's paths (exact arcs, gentle entries) or the 2016 STEP-NC robot thesis's points,"
                + " for fresa toolpath and fresa robot (--paths)");
        paths.addActionListener(e -> pathsChosen());
        top.add(pathsLabel);
        top.add(paths);
        top.add(fileLabel);

        tree.setName("stepnc-tree");
        tree.setRootVisible(true);
        // rows of one height: the tree then lays out only the rows in view, not all of them
        tree.setRowHeight(tree.getFontMetrics(tree.getFont()).getHeight() + 4);
        tree.setLargeModel(true);
        tree.addTreeSelectionListener(e -> selectionChanged());
        JPanel left = Captions.above("Workplans and workingsteps", KeyEvent.VK_W, tree, new JScrollPane(tree));
        problems.onSelect(this::showProblem);
        left.add(problems, BorderLayout.SOUTH);

        details.setEditable(false);
        details.setName("stepnc-details");
        details.setLineWrap(true);
        details.setWrapStyleWord(true);
        JSplitPane rightSplit = new JSplitPane(JSplitPane.VERTICAL_SPLIT, new JScrollPane(details), toolpathView());
        rightSplit.setResizeWeight(0.3);
        JPanel right = Captions.above("Selected workingstep", KeyEvent.VK_S, details, rightSplit);

        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left, right);
        split.setResizeWeight(0.35);
        split.setDividerLocation(360);
        panel.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        panel.add(top, BorderLayout.NORTH);
        panel.add(split, BorderLayout.CENTER);
        ctx.model().addListener(e -> {
            if (MainViewModel.JOB.equals(e.getPropertyName())) {
                jobChanged();
            }
        });
        panel.setTransferHandler(new FileDrop());
        tree.setTransferHandler(new FileDrop());
        details.setTransferHandler(new FileDrop());
    }

    /** The plot with the layer selector, the replay slider and the cycle time above it. */
    private JPanel toolpathView() {
        layers.setName("stepnc-layer");
        layers.addActionListener(e -> {
            if (!updating && layers.getSelectedIndex() >= 0) {
                vm.selectLayer(layers.getSelectedIndex());
                showToolpath(true);
            }
        });
        JLabel layerLabel = new JLabel("Layer:");
        layerLabel.setDisplayedMnemonic(KeyEvent.VK_L);
        layerLabel.setLabelFor(layers);
        replay.setName("stepnc-replay");
        replay.setMajorTickSpacing(StepNcViewModel.REPLAY_STEPS / 10);
        replay.setPaintTicks(true);
        replay.getAccessibleContext().setAccessibleName("Replay position");
        replay.addChangeListener(e -> {
            if (!updating) {
                vm.setReplay(replay.getValue());
                showToolpath(false);
            }
        });
        JLabel replayLabel = new JLabel("Replay:");
        replayLabel.setDisplayedMnemonic(KeyEvent.VK_R);
        replayLabel.setLabelFor(replay);
        play.setName("stepnc-play");
        play.setMnemonic(KeyEvent.VK_P);
        play.addActionListener(e -> togglePlay());
        replayText.setName("stepnc-replay-text");
        cycleText.setName("stepnc-cycle-time");

        JPanel row = new JPanel(new BorderLayout(6, 0));
        JPanel west = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        west.add(layerLabel);
        west.add(layers);
        west.add(play);
        west.add(replayLabel);
        row.add(west, BorderLayout.WEST);
        row.add(replay, BorderLayout.CENTER);
        JPanel controls = new JPanel(new BorderLayout(0, 2));
        controls.setBorder(BorderFactory.createEmptyBorder(4, 2, 2, 2));
        controls.add(row, BorderLayout.NORTH);
        controls.add(replayText, BorderLayout.CENTER);
        JPanel texts = new JPanel(new java.awt.GridLayout(0, 1));
        texts.add(cycleText);
        legend.setName("stepnc-legend");
        // parsed here, with the window: the first HTML text of a JVM took 30 to 40 ms of the event
        // thread when the first program was shown; the grid keeps the hidden label's row
        legend.setText("<html><font color='#1565C0'>blue: feed</font>, <font color='#E53935'>red dashed: rapid"
                + "</font>, <font color='#2E7D32'>green: cut so far</font>, <font color='#FF8F00'>orange: the tool"
                + "</font>, black: the feature</html>");
        legend.setVisible(false);
        texts.add(legend);
        controls.add(texts, BorderLayout.SOUTH);
        JPanel view = new JPanel(new BorderLayout());
        view.add(controls, BorderLayout.NORTH);
        view.add(plot, BorderLayout.CENTER);
        return view;
    }

    private void togglePlay() {
        if (player.isRunning()) {
            player.stop();
            play.setText("Play");
            return;
        }
        if (replay.getValue() >= replay.getMaximum()) {
            replay.setValue(0);
        }
        player.start();
        play.setText("Pause");
    }

    private void step() {
        if (replay.getValue() >= replay.getMaximum() || !replay.isEnabled()) {
            togglePlay();
            return;
        }
        replay.setValue(replay.getValue() + 1);
    }

    private void choose() {
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.STEPNC);
        if (fc.showOpenDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION) {
            open(FileChoosers.chosen(fc));
        }
    }

    /**
     * A job with a STEP-NC file shows that file here; a job without one (New, another Open, an
     * undo) shows the empty tab, never the last job's part.
     */
    /** The path conventions the list shows. */
    private org.fresa.toolpath.PathConvention chosenPaths() {
        int i = paths.getSelectedIndex();
        return StepNcViewModel.PATHS.get(Math.max(0, i));
    }

    /** A path convention picked: the job's STEP-NC settings carry it, and the file is planned again. */
    private void pathsChosen() {
        if (updating) {
            return;
        }
        var s = ctx.model().job().stepnc();
        if (s.isPresent() && s.get().paths() != chosenPaths()) {
            ctx.model().setJob(ctx.model().job().withStepnc(s.get().withPaths(chosenPaths())));
        }
    }

    private void jobChanged() {
        var settings = ctx.model().job().stepnc();
        if (settings.isPresent() && settings.get().paths() != chosenPaths()) {
            updating = true;
            paths.setSelectedIndex(StepNcViewModel.PATHS.indexOf(settings.get().paths()));
            updating = false;
        }
        if (settings.isPresent()
                && settings.get().file().equals(loadedFile)
                && settings.get().paths() != loadedPaths) {
            // the same file with other path conventions: planned again
            Path f = loadedFile;
            clear();
            open(f);
            return;
        }
        Optional<Path> want = settings.map(JobSettings.StepNcSettings::file);
        if (want.isEmpty()) {
            if (loadedFile != null || requestedFile != null) {
                clear();
            }
            return;
        }
        Path f = want.get();
        if (!f.equals(loadedFile) && !f.equals(requestedFile)) {
            clear();
            open(f);
        }
    }

    /** The empty tab: no program, no tree, no plot. */
    private void clear() {
        player.stop();
        play.setText("Play");
        vm = new StepNcViewModel();
        loadedFile = null;
        loadedPaths = null;
        requestedFile = null;
        preparedPlot = null;
        preparedDetails = null;
        fileLabel.setText("No file read. Open a STEP-NC file or drop one here.");
        refresh(new DefaultTreeModel(new DefaultMutableTreeNode("No file")));
    }

    /** A program and its toolpaths, read and planned in one background task. */
    private record Loaded(
            StepNcProgram program,
            ToolpathPlanner.Plan plan,
            org.fresa.model.CycleTime time,
            List<String> said,
            DefaultTreeModel tree,
            org.fresa.chart.PlotScene firstPlot,
            List<String> firstDetails) {}

    void open(Path file) {
        requestedFile = file;
        int generation = ctx.model().generation();
        JobSettings.StepNcSettings settings =
                StepNcViewModel.settingsFor(ctx.model().job(), file, chosenPaths());
        org.fresa.job.Job job = ctx.model().job();
        ctx.tasks()
                .start(
                        "Reading and planning " + file.getFileName(),
                        progress -> {
                            // planned as fresa run plans it: with the job's choices where it holds this file
                            ToolpathService.Planned planned =
                                    ToolpathService.compute(file, settings.choices(), progress);
                            StepNcProgram p = planned.program();
                            ToolpathPlanner.Plan plan = planned.plan();
                            // a tree model no tree shows yet belongs to no thread: a big file's tree is built here
                            org.fresa.model.CycleTime time = StepNcViewModel.programTimeOf(plan);
                            // what the job's run says of it, as the service that runs it says it
                            List<String> said = StepNcViewModel.problemsOf(job, file, planned, settings);
                            // the first workingstep's plot, from a view model of this thread in the tab's first state
                            StepNcViewModel first = new StepNcViewModel();
                            first.load(p);
                            first.planned(plan, time, said);
                            return new Loaded(
                                    p,
                                    plan,
                                    time,
                                    said,
                                    new DefaultTreeModel(toSwing(StepNcViewModel.treeOf(p))),
                                    first.plot(),
                                    first.details());
                        },
                        loaded -> {
                            if (generation != ctx.model().generation() || !file.equals(requestedFile)) {
                                // another document (or file) was asked for while this one was read
                                return;
                            }
                            StepNcProgram program = loaded.program();
                            vm.load(program);
                            vm.planned(loaded.plan(), loaded.time(), loaded.said());
                            problems.show(vm.problems());
                            preparedPlot = loaded.firstPlot();
                            preparedDetails = loaded.firstDetails();
                            loadedFile = file;
                            loadedPaths = settings.paths();
                            if (!ctx.model().job().stepnc().equals(Optional.of(settings))) {
                                ctx.model().setJob(ctx.model().job().withStepnc(settings));
                            }
                            fileLabel.setText(file.getFileName() + ": "
                                    + program.workingsteps().size() + " workingsteps, "
                                    + program.skipped().size() + " skipped, "
                                    + program.unknownEntities().size()
                                    + " entity types not interpreted");
                            refresh(loaded.tree());
                        });
    }

    private void refresh(DefaultTreeModel model) {
        tree.setModel(model);
        // a node of thousands of rows (a big file's skipped workingsteps) stays closed: opening it
        // here would lay out every row on the event thread; the planner opens it when he wants it
        for (int i = 0; i < Math.min(tree.getRowCount(), 200); i++) {
            if (tree.getPathForRow(i).getLastPathComponent() instanceof DefaultMutableTreeNode d
                    && d.getChildCount() <= 200) {
                tree.expandRow(i);
            }
        }
        tree.scrollRectToVisible(new java.awt.Rectangle(0, 0, 1, 1));
        showSelection();
    }

    private static DefaultMutableTreeNode toSwing(StepNcViewModel.Node n) {
        DefaultMutableTreeNode d = new DefaultMutableTreeNode(n);
        for (StepNcViewModel.Node c : n.children()) {
            d.add(toSwing(c));
        }
        return d;
    }

    /** Selects the workingstep a planning problem names, so that its details and plot show. */
    private void showProblem(WarningList.Warning w) {
        vm.workingstepNamedIn(w.text()).ifPresent(ws -> {
            java.util.Enumeration<javax.swing.tree.TreeNode> all =
                    ((DefaultMutableTreeNode) tree.getModel().getRoot()).breadthFirstEnumeration();
            while (all.hasMoreElements()) {
                if (all.nextElement() instanceof DefaultMutableTreeNode d
                        && d.getUserObject() instanceof StepNcViewModel.Node n
                        && n.workingstep().equals(Optional.of(ws))) {
                    TreePath path = new TreePath(d.getPath());
                    tree.setSelectionPath(path);
                    tree.scrollPathToVisible(path);
                    return;
                }
            }
        });
    }

    private void selectionChanged() {
        TreePath path = tree.getSelectionPath();
        if (path != null
                && path.getLastPathComponent() instanceof DefaultMutableTreeNode d
                && d.getUserObject() instanceof StepNcViewModel.Node n) {
            vm.select(n.workingstep());
            showSelection();
            // keep the start of the labels in view: selecting a long row scrolls the tree sideways
            javax.swing.SwingUtilities.invokeLater(() -> {
                if (tree.getParent() instanceof javax.swing.JViewport vp) {
                    vp.setViewPosition(new java.awt.Point(0, vp.getViewPosition().y));
                }
            });
        }
    }

    private void showSelection() {
        details.setText(String.join("\n", preparedDetails != null ? preparedDetails : vm.details()));
        preparedDetails = null;
        details.setCaretPosition(0);
        updating = true;
        try {
            layers.setModel(new DefaultComboBoxModel<>(vm.layerChoices().toArray(new String[0])));
            layers.setSelectedIndex(vm.layer());
            layers.setEnabled(vm.layers().size() > 1);
        } finally {
            updating = false;
        }
        showToolpath(true);
    }

    /** The replay controls and the plot from the view model; {@code fit} refits the view. */
    private void showToolpath(boolean fit) {
        boolean has = vm.shown().isPresent();
        updating = true;
        try {
            replay.setValue(vm.replay());
            replay.setEnabled(has);
            play.setEnabled(has);
        } finally {
            updating = false;
        }
        replayText.setText(vm.replayText());
        cycleText.setText(vm.cycleTimeShort());
        legend.setVisible(has);
        List<String> ct = vm.cycleTime();
        cycleText.setToolTipText(ct.isEmpty() ? null : String.join(". ", ct));
        org.fresa.chart.PlotScene scene = preparedPlot != null ? preparedPlot : vm.plot();
        preparedPlot = null;
        if (fit) {
            plot.show(scene);
        } else {
            plot.update(scene);
        }
    }

    /** Accepts one dropped file and reads it. */
    private final class FileDrop extends TransferHandler {
        private static final long serialVersionUID = 1L;

        @Override
        public boolean canImport(TransferSupport support) {
            return support.isDataFlavorSupported(DataFlavor.javaFileListFlavor);
        }

        @Override
        public boolean importData(TransferSupport support) {
            if (!canImport(support)) {
                return false;
            }
            try {
                List<?> files = (List<?>) support.getTransferable().getTransferData(DataFlavor.javaFileListFlavor);
                if (files.isEmpty() || !(files.get(0) instanceof File f)) {
                    return false;
                }
                open(f.toPath());
                return true;
            } catch (java.awt.datatransfer.UnsupportedFlavorException | java.io.IOException e) {
                return false;
            }
        }
    }
}
