package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JTabbedPane;
import javax.swing.KeyStroke;
import javax.swing.WindowConstants;
import javax.swing.filechooser.FileNameExtensionFilter;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobRunner;
import org.fresa.job.JobTask;
import org.fresa.job.TaskOutcome;
import org.fresa.model.CamInputException;

/** The main window: menu, the eight module tabs sharing one job, and the status bar. */
public final class MainWindow extends JFrame {

    private static final long serialVersionUID = 1L;

    private final transient MainViewModel model;
    private final JTabbedPane tabs = new JTabbedPane();
    private final StatusBar status = new StatusBar();
    private final transient BackgroundTasks tasks;
    private final transient List<ModuleTab> moduleTabs;
    private final JMenu recentMenu = new JMenu("Recent jobs");
    private final transient RobotRunModel runs = new RobotRunModel();
    private final JMenuItem undoItem = item("Undo", 'U', KeyStroke.getKeyStroke("ctrl Z"), this::undo);
    private final JMenuItem redoItem = item("Redo", 'R', KeyStroke.getKeyStroke("ctrl Y"), this::redo);

    MainWindow(MainViewModel model) {
        super("Fresa");
        this.model = model;
        this.tasks = new BackgroundTasks(status, this);
        setName("main");
        setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                quit();
            }
        });
        // results belong to the document: New and Open drop them before the tabs show the new job
        model.addListener(e -> {
            if (MainViewModel.DOCUMENT.equals(e.getPropertyName())) {
                runs.clear();
            }
        });
        moduleTabs = Tabs.create(new AppContext(model, tasks, this, runs));
        tabs.setName("tabs");
        for (int i = 0; i < moduleTabs.size(); i++) {
            ModuleTab t = moduleTabs.get(i);
            tabs.addTab(t.title(), t.component());
            tabs.setMnemonicAt(i, KeyEvent.VK_1 + i);
            tabs.setToolTipTextAt(i, t.title() + " (Alt+" + (i + 1) + ")");
        }
        setJMenuBar(menuBar());
        getContentPane().add(tabs, BorderLayout.CENTER);
        getContentPane().add(status, BorderLayout.SOUTH);
        setPreferredSize(new Dimension(1280, 820));
        setMinimumSize(new Dimension(800, 560));
        pack();
        setLocationRelativeTo(null);
        model.addListener(e -> {
            updateTitle();
            updateHistory();
            updateRunTicks();
        });
        updateTitle();
        updateHistory();
        updateRunTicks();
    }

    private void updateTitle() {
        setTitle(
                model.file().isEmpty()
                                && !model.isDirty()
                                && "untitled".equals(model.job().name())
                        ? "Fresa"
                        : model.title());
    }

    /** What each task's tick in the Job menu says. */
    private static final java.util.Map<JobTask, String> RUN_LABELS = new java.util.EnumMap<>(java.util.Map.of(
            JobTask.STEPNC,
            "STEP-NC description (stepnc)",
            JobTask.TOOLPATH,
            "Toolpaths and NC program (toolpath)",
            JobTask.ROBOT,
            "Robot trajectory and programs (robot)",
            JobTask.POCKET,
            "Pocket program (pocket)",
            JobTask.CUT,
            "Sheet cutting program (cut)",
            JobTask.GRADE,
            "Graded sizes (grade)",
            JobTask.SOLE,
            "Sole mould programs (sole)"));

    private final transient java.util.Map<JobTask, javax.swing.JCheckBoxMenuItem> runTicks =
            new java.util.EnumMap<>(JobTask.class);

    /** Ticks what the job runs; a module without its settings can be ticked only once it has them. */
    private void updateRunTicks() {
        var job = model.job();
        for (var e : runTicks.entrySet()) {
            boolean on = job.runs().contains(e.getKey());
            e.getValue().setSelected(on);
            e.getValue().setEnabled(on || hasSettings(job, e.getKey()));
        }
    }

    private static boolean hasSettings(org.fresa.job.Job job, JobTask t) {
        switch (t) {
            case STEPNC:
            case TOOLPATH:
                return job.stepnc().isPresent();
            case ROBOT:
                return job.stepnc().isPresent() && job.robot().isPresent();
            case POCKET:
                return job.pocket().isPresent();
            case CUT:
                return job.cutting().isPresent();
            case GRADE:
                return job.grading().isPresent();
            case SOLE:
                return job.sole().isPresent();
            default:
                return false;
        }
    }

    /**
     * A tick in the Job menu: the job runs that module too, or no longer; one always stays. A
     * module without settings cannot run: ticking one that has them drops those (a new job's).
     */
    private void tickRun(JobTask t, boolean on) {
        java.util.EnumSet<JobTask> r = java.util.EnumSet.copyOf(model.job().runs());
        if (on) {
            r.removeIf(x -> !hasSettings(model.job(), x));
            r.add(t);
        } else {
            r.remove(t);
        }
        if (r.isEmpty()) {
            status.message.setText("A job runs at least one module: tick another one first");
        } else {
            model.setJob(model.job().withRuns(r));
        }
        updateRunTicks();
    }

    private void updateHistory() {
        undoItem.setEnabled(model.canUndo());
        redoItem.setEnabled(model.canRedo());
    }

    private void undo() {
        if (model.undo()) {
            status.message.setText("Undone");
        }
    }

    private void redo() {
        if (model.redo()) {
            status.message.setText("Redone");
        }
    }

    private JMenuBar menuBar() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.setMnemonic('F');
        file.add(item("New", 'N', KeyStroke.getKeyStroke("ctrl N"), this::newJob));
        file.add(item("Open job...", 'O', KeyStroke.getKeyStroke("ctrl O"), this::chooseAndOpen));
        file.add(item("Save", 'S', KeyStroke.getKeyStroke("ctrl S"), this::save));
        file.add(item("Save as...", 'A', KeyStroke.getKeyStroke("ctrl shift S"), this::saveAs));
        recentMenu.setMnemonic('R');
        file.add(recentMenu);
        refreshOnOpen(file, this::fillRecent);
        file.addSeparator();
        file.add(item("Export plot (PNG/SVG)...", 'E', KeyStroke.getKeyStroke("ctrl E"), this::exportPlot));
        file.addSeparator();
        file.add(item("Quit", 'Q', KeyStroke.getKeyStroke("ctrl Q"), this::quit));
        bar.add(file);
        JMenu edit = new JMenu("Edit");
        edit.setMnemonic('E');
        edit.add(undoItem);
        edit.add(redoItem);
        // Ctrl+Shift+Z redoes too, as in most editors
        getRootPane()
                .getInputMap(javax.swing.JComponent.WHEN_IN_FOCUSED_WINDOW)
                .put(KeyStroke.getKeyStroke("ctrl shift Z"), "fresa-redo");
        getRootPane().getActionMap().put("fresa-redo", new javax.swing.AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                redo();
            }
        });
        bar.add(edit);
        JMenu job = new JMenu("Job");
        job.setMnemonic('J');
        job.add(item("Run job into folder...", 'R', KeyStroke.getKeyStroke("F5"), this::runJob));
        job.add(item("Cancel running task", 'C', KeyStroke.getKeyStroke("ESCAPE"), tasks::cancel));
        job.addSeparator();
        JMenuItem title = new JMenuItem("Run executes:");
        title.setEnabled(false);
        job.add(title);
        for (JobTask t : JobTask.values()) {
            javax.swing.JCheckBoxMenuItem tick = new javax.swing.JCheckBoxMenuItem(RUN_LABELS.get(t));
            tick.setName("run-" + t.id());
            tick.addActionListener(e -> tickRun(t, tick.isSelected()));
            runTicks.put(t, tick);
            job.add(tick);
        }
        refreshOnOpen(job, this::updateRunTicks);
        bar.add(job);
        bar.add(HelpMenu.create(this));
        return bar;
    }

    /** The menu shows what is true when it opens: the recent jobs, the tasks Run executes. */
    private static void refreshOnOpen(JMenu menu, Runnable refresh) {
        menu.addMenuListener(new javax.swing.event.MenuListener() {
            @Override
            public void menuSelected(javax.swing.event.MenuEvent e) {
                refresh.run();
            }

            @Override
            public void menuDeselected(javax.swing.event.MenuEvent e) {}

            @Override
            public void menuCanceled(javax.swing.event.MenuEvent e) {}
        });
    }

    private static JMenuItem item(String text, char mnemonic, KeyStroke key, Runnable action) {
        JMenuItem i = new JMenuItem(text);
        i.setMnemonic(mnemonic);
        i.setAccelerator(key);
        i.addActionListener(e -> action.run());
        return i;
    }

    private void fillRecent() {
        recentMenu.removeAll();
        List<Path> recent = model.recentJobs();
        if (recent.isEmpty()) {
            JMenuItem none = new JMenuItem("(none)");
            none.setEnabled(false);
            recentMenu.add(none);
        }
        int n = 1;
        for (Path p : recent) {
            JMenuItem i = new JMenuItem(n + " " + p.getFileName() + "  (" + p.getParent() + ")");
            if (n <= 9) {
                i.setMnemonic(KeyEvent.VK_0 + n);
            }
            i.setName("recent-" + n);
            // another job replaces this one: its unsaved changes are asked about first, as for Open
            i.addActionListener(e -> {
                if (confirmDiscard()) {
                    openJob(p);
                }
            });
            recentMenu.add(i);
            n++;
        }
    }

    public MainViewModel model() {
        return model;
    }

    JTabbedPane tabs() {
        return tabs;
    }

    /** The module tab of a class (the GUI tests read the Position tab's measurements). */
    <T extends ModuleTab> T moduleTab(Class<T> type) {
        return moduleTabs.stream()
                .filter(type::isInstance)
                .map(type::cast)
                .findFirst()
                .orElseThrow();
    }

    public int tabCount() {
        return tabs.getTabCount();
    }

    private boolean confirmDiscard() {
        if (!model.isDirty()) {
            return true;
        }
        int a = JOptionPane.showConfirmDialog(
                this,
                "The job has unsaved changes. Save them first?",
                "Fresa",
                JOptionPane.YES_NO_CANCEL_OPTION,
                JOptionPane.WARNING_MESSAGE);
        if (a == JOptionPane.YES_OPTION) {
            return save();
        }
        return a == JOptionPane.NO_OPTION;
    }

    private void newJob() {
        if (confirmDiscard()) {
            model.newJob();
            status.message.setText("New job");
        }
    }

    private void chooseAndOpen() {
        if (!confirmDiscard()) {
            return;
        }
        JFileChooser fc = jobChooser();
        if (fc.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
            openJob(fc.getSelectedFile().toPath());
        }
    }

    /** Opens a job file, showing a dialog with the reason when it is refused. */
    public void openJob(Path p) {
        try {
            model.open(p);
            status.message.setText("Opened " + p);
        } catch (CamInputException e) {
            Dialogs.error(this, "Open job", e.getMessage());
        }
    }

    private JFileChooser jobChooser() {
        JFileChooser fc = new JFileChooser(
                model.file().map(Path::getParent).map(Path::toFile).orElse(null));
        fc.setFileFilter(new FileNameExtensionFilter("Fresa jobs (*.xml)", "xml"));
        return fc;
    }

    private boolean save() {
        try {
            if (model.save()) {
                status.message.setText("Saved " + model.file().orElseThrow());
                return true;
            }
            return saveAs();
        } catch (IOException e) {
            Dialogs.error(this, "Save job", e.getMessage());
            return false;
        }
    }

    private boolean saveAs() {
        JFileChooser fc = jobChooser();
        if (fc.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) {
            return false;
        }
        try {
            model.saveAs(fc.getSelectedFile().toPath());
            status.message.setText("Saved " + model.file().orElseThrow());
            return true;
        } catch (IOException e) {
            Dialogs.error(this, "Save job", e.getMessage());
            return false;
        }
    }

    private Optional<PlotPanel> currentPlot() {
        int i = tabs.getSelectedIndex();
        return i < 0 ? Optional.empty() : moduleTabs.get(i).plot();
    }

    private void exportPlot() {
        Optional<PlotPanel> plot = currentPlot();
        if (plot.isEmpty()) {
            Dialogs.info(this, "Export plot", "This tab has no plot to export.");
            return;
        }
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.PLOT);
        if (fc.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path p = FileChoosers.chosen(fc);
        if (!p.getFileName().toString().contains(".")) {
            boolean svg = fc.getFileFilter().getDescription().startsWith("SVG");
            p = p.resolveSibling(p.getFileName() + (svg ? ".svg" : ".png"));
        }
        try {
            plot.get().export(p);
            status.message.setText("Exported " + p);
        } catch (IOException e) {
            Dialogs.error(this, "Export plot", e.getMessage());
        }
    }

    private void runJob() {
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.FOLDER);
        fc.setDialogTitle("Output folder");
        if (fc.showDialog(this, "Run here") != JFileChooser.APPROVE_OPTION) {
            return;
        }
        Path dir = FileChoosers.chosen(fc);
        var job = model.job();
        int generation = model.generation();
        String what = String.join(", ", job.runs().stream().map(JobTask::id).toList());
        tasks.start("Run " + what, pm -> JobRunner.run(job, new OutputFolder(dir), pm), o -> {
            // the programs of this run are the job's, unless another job was opened meanwhile
            if (generation == model.generation()
                    && job.runs().contains(JobTask.ROBOT)
                    && job.robot().isPresent()) {
                Path folder = job.runs().size() == 1 ? dir : dir.resolve(JobTask.ROBOT.id());
                runs.setWritten(new RobotRunModel.Written(
                        job.robot().get().robot(),
                        folder,
                        o.files().stream().filter(f -> f.startsWith(folder)).toList()));
            }
            showOutcome(o);
        });
    }

    private void showOutcome(TaskOutcome o) {
        StringBuilder sb = new StringBuilder();
        for (String p : o.problems()) {
            sb.append(p).append('\n');
        }
        for (Path f : o.files()) {
            sb.append("wrote ").append(f).append('\n');
        }
        if (o.exitStatus() == 0) {
            Dialogs.info(this, "Run job", sb.length() == 0 ? "Done." : sb.toString());
        } else {
            Dialogs.error(this, "Run job", sb.toString());
        }
    }

    private void quit() {
        if (confirmDiscard()) {
            tasks.cancel();
            dispose();
            System.exit(0);
        }
    }
}
