package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.ExecutionException;
import javax.swing.BorderFactory;
import javax.swing.DefaultCellEditor;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTable;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.SwingWorker;
import javax.swing.Timer;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.DefaultTableCellRenderer;
import org.fresa.kin.Robot;
import org.fresa.model.CamInputException;

/**
 * The Robot tab: choose a built-in robot or open a robot file, edit its DH table (type, theta,
 * d, a, alpha as expressions such as {@code q2 - 90}, the limits), its tool frame or Tricept
 * dimensions, save it as a robot file, and read its symbolic forward kinematics, derived again
 * in the background whenever the table changes. A valid edited robot is kept as a file and named
 * in the job, so that Compute, Job &gt; Run and {@code fresa run} all use it.
 */
final class RobotTab implements ModuleTab {

    private static final Color BAD = new Color(255, 215, 215);
    private static final Color READ_ONLY = new Color(238, 238, 238);
    private static final java.util.concurrent.ExecutorService SYMBOLIC = BackgroundThreads.single("fresa-symbolic");

    private final AppContext ctx;
    private final RobotViewModel vm = new RobotViewModel();
    private final JPanel panel = new JPanel(new BorderLayout());
    private final JComboBox<String> robots =
            new JComboBox<>(RobotViewModel.builtIns().toArray(String[]::new));
    private final DhModel table = new DhModel();
    private final JTable dh = new JTable(table) {
        private static final long serialVersionUID = 1L;

        /** Typing into a cell replaces its text, as in a spreadsheet; F2 or a double click edits it. */
        @Override
        public boolean editCellAt(int row, int column, java.util.EventObject e) {
            boolean editing = super.editCellAt(row, column, e);
            if (editing && e instanceof KeyEvent && getEditorComponent() instanceof JTextField f) {
                f.setText("");
            }
            return editing;
        }
    };
    private final JLabel messages = new JLabel(" ");
    private final JLabel uses = new JLabel(" ");
    private final JPanel paramPanel = new JPanel(new GridBagLayout());
    private final JTextArea params = new JTextArea(3, 40);
    private final JTextArea symbolic = new JTextArea(12, 60);
    private final Timer commitTimer;
    private JTextField[] paramFields = new JTextField[0];
    private final JTextField spindle = new JTextField(14);
    private final JTextField toolLength = new JTextField(6);
    private final JLabel spindleMessage = new JLabel(" ");
    private final JLabel toolLengthMessage = new JLabel(" ");
    private boolean updating;
    private int symbolicGeneration;
    private Robot symbolicOf;

    RobotTab(AppContext ctx) {
        this.ctx = ctx;
        robots.setName("robot-choice");
        robots.setEditable(false);
        JLabel robotLabel = new JLabel("Robot:");
        robotLabel.setDisplayedMnemonic(KeyEvent.VK_R);
        robotLabel.setLabelFor(robots);
        robots.addActionListener(e -> {
            if (!updating && robots.getSelectedItem() instanceof String s) {
                choose(s);
            }
        });
        JButton open = Buttons.of("Open robot file...", "robot-open", KeyEvent.VK_O, () -> openFile());
        JButton save = Buttons.of("Save robot as file...", "robot-save", KeyEvent.VK_A, () -> saveFile());
        JButton fk = Buttons.of("Symbolic FK", "robot-symbolic", KeyEvent.VK_K, () -> computeSymbolic());
        JButton export = Buttons.of("Export symbolic FK...", "robot-export", KeyEvent.VK_E, () -> exportSymbolic());
        JPanel top = Buttons.row(robotLabel, robots, open, save, fk, export);

        dh.setName("robot-dh");
        dh.setFillsViewportHeight(true);
        dh.setRowHeight(Math.max(dh.getRowHeight(), 22));
        dh.setSurrendersFocusOnKeystroke(true);
        dh.putClientProperty("terminateEditOnFocusLost", Boolean.TRUE);
        dh.setDefaultRenderer(Object.class, new CellRenderer());
        JComboBox<String> types = new JComboBox<>(new String[] {"R", "P"});
        types.setName("robot-dh-type");
        dh.getColumnModel().getColumn(RobotViewModel.TYPE).setCellEditor(new DefaultCellEditor(types));
        for (int c = 0; c < RobotViewModel.COLUMNS.length; c++) {
            dh.getColumnModel().getColumn(c).setPreferredWidth(c == 0 ? 45 : c == RobotViewModel.TYPE ? 70 : 150);
        }
        JLabel dhLabel = new JLabel("Denavit-Hartenberg table, A = Rz(theta) Tz(d) Tx(a) Rx(alpha); cells are"
                + " expressions such as q2 - 90 (type to replace, F2 to edit, Enter to commit)");
        dhLabel.setDisplayedMnemonic(KeyEvent.VK_D);
        dhLabel.setLabelFor(dh);
        messages.setName("robot-messages");
        messages.setForeground(new Color(170, 0, 0));
        uses.setName("robot-uses");
        JPanel upper = new JPanel(new BorderLayout(4, 4));
        upper.add(dhLabel, BorderLayout.NORTH);
        JScrollPane dhScroll = new JScrollPane(dh);
        dhScroll.setPreferredSize(new java.awt.Dimension(700, 7 * dh.getRowHeight() + 8));
        upper.add(dhScroll, BorderLayout.CENTER);
        JPanel south = new JPanel(new BorderLayout(4, 2));
        JPanel msgs = new JPanel(new java.awt.GridLayout(2, 1));
        msgs.add(messages);
        msgs.add(uses);
        south.add(msgs, BorderLayout.NORTH);
        paramPanel.setBorder(BorderFactory.createTitledBorder("Parameters"));
        JPanel centre = new JPanel(new BorderLayout());
        centre.add(paramPanel, BorderLayout.CENTER);
        centre.add(toolPanel(), BorderLayout.SOUTH);
        south.add(centre, BorderLayout.CENTER);
        params.setEditable(false);
        params.setName("robot-parameters");
        params.setBackground(panel.getBackground());
        south.add(params, BorderLayout.SOUTH);
        upper.add(south, BorderLayout.SOUTH);

        symbolic.setEditable(false);
        symbolic.setName("robot-fk");
        symbolic.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        JPanel lower = Captions.above(
                "Symbolic forward kinematics (Symja), derived from the table above",
                KeyEvent.VK_S,
                symbolic,
                new JScrollPane(symbolic));

        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, upper, lower);
        split.setResizeWeight(0);
        panel.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        panel.add(top, BorderLayout.NORTH);
        panel.add(split, BorderLayout.CENTER);
        commitTimer = new Timer(350, e -> commit());
        commitTimer.setRepeats(false);
        ctx.model().addListener(e -> {
            if (MainViewModel.JOB.equals(e.getPropertyName())) {
                vm.fromJob(ctx.model().job()).ifPresent(this::chooseQuietly);
                showJobsTool();
            }
        });
        showJobsTool();
        // the derivation waits until the tab is shown (see computeSymbolic)
        panel.addHierarchyListener(e -> {
            if ((e.getChangeFlags() & java.awt.event.HierarchyEvent.SHOWING_CHANGED) != 0 && panel.isShowing()) {
                computeSymbolic();
            }
        });
        refresh();
    }

    /**
     * The tool on the flange, the job's: the spindle nose in the flange frame and the tool length
     * from the nose to the tip, each field marked with its message beside it while it is wrong
     * (the job then keeps the last good value).
     */
    private JPanel toolPanel() {
        JPanel p = new JPanel(new GridBagLayout());
        p.setBorder(BorderFactory.createTitledBorder("Tool on the flange (the job's)"));
        spindle.setName("robot-spindle");
        toolLength.setName("robot-tool-length");
        spindleMessage.setName("robot-spindle-message");
        toolLengthMessage.setName("robot-tool-length-message");
        spindleMessage.setForeground(new Color(170, 0, 0));
        toolLengthMessage.setForeground(new Color(170, 0, 0));
        JLabel sl = new JLabel("Spindle X,Y,Z[,RX,RY,RZ] (mm, deg):");
        sl.setDisplayedMnemonic(KeyEvent.VK_P);
        sl.setLabelFor(spindle);
        JLabel tl = new JLabel("Tool length (mm):");
        tl.setDisplayedMnemonic(KeyEvent.VK_L);
        tl.setLabelFor(toolLength);
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(1, 4, 1, 4);
        c.anchor = GridBagConstraints.WEST;
        c.gridy = 0;
        p.add(sl, c);
        p.add(spindle, c);
        p.add(spindleMessage, c);
        c.gridy = 1;
        p.add(tl, c);
        p.add(toolLength, c);
        p.add(toolLengthMessage, c);
        TextChanges.onChange(spindle, () -> {
            if (!updating) {
                vm.setSpindle(spindle.getText());
                toolEdited();
            }
        });
        TextChanges.onChange(toolLength, () -> {
            if (!updating) {
                vm.setToolLength(toolLength.getText());
                toolEdited();
            }
        });
        markTool();
        return p;
    }

    /** A tool field changed: marks it, and a good value goes into the job at once. */
    private void toolEdited() {
        markTool();
        org.fresa.job.Job j = vm.applyToolTo(ctx.model().job());
        if (!j.equals(ctx.model().job())) {
            ctx.model().setJob(j);
        }
    }

    /** The job's spindle and tool length in the fields, when the job changed them (a job opened). */
    private void showJobsTool() {
        if (!vm.loadTool(ctx.model().job())) {
            return;
        }
        updating = true;
        try {
            spindle.setText(vm.spindleText());
            toolLength.setText(vm.toolLengthText());
        } finally {
            updating = false;
        }
        markTool();
    }

    private void markTool() {
        var sp = vm.spindleProblem();
        var tp = vm.toolLengthProblem();
        spindle.setBackground(sp.isPresent() ? BAD : Color.WHITE);
        toolLength.setBackground(tp.isPresent() ? BAD : Color.WHITE);
        spindleMessage.setText(sp.orElse(" "));
        toolLengthMessage.setText(tp.orElse(" "));
        spindle.setToolTipText(sp.orElse(Tooltips.SPINDLE));
        toolLength.setToolTipText(tp.orElse(Tooltips.TOOL_LENGTH));
    }

    @Override
    public String title() {
        return "Robot";
    }

    @Override
    public JComponent component() {
        return panel;
    }

    /** The table model over the view model's cells. */
    private final class DhModel extends AbstractTableModel {
        private static final long serialVersionUID = 1L;

        @Override
        public int getRowCount() {
            return vm.rowCount();
        }

        @Override
        public int getColumnCount() {
            return RobotViewModel.COLUMNS.length;
        }

        @Override
        public String getColumnName(int c) {
            return RobotViewModel.COLUMNS[c];
        }

        @Override
        public Object getValueAt(int r, int c) {
            return vm.cell(r, c);
        }

        @Override
        public boolean isCellEditable(int r, int c) {
            return vm.isEditable(r, c);
        }

        @Override
        public void setValueAt(Object v, int r, int c) {
            if (v == null || v.toString().equals(vm.cell(r, c))) {
                return;
            }
            vm.setCell(r, c, v.toString());
            fireTableRowsUpdated(r, r);
            edited();
        }
    }

    /** Marks bad cells red with their message as tooltip, read-only cells grey. */
    private final class CellRenderer extends DefaultTableCellRenderer {
        private static final long serialVersionUID = 1L;

        @Override
        public Component getTableCellRendererComponent(
                JTable t, Object value, boolean selected, boolean focus, int row, int col) {
            Component c = super.getTableCellRendererComponent(t, value, selected, focus, row, col);
            var problem = vm.problem(row, col);
            setToolTipText(problem.orElse(vm.isEditable(row, col) ? "Edit: type, then Enter" : null));
            if (problem.isPresent()) {
                c.setBackground(BAD);
                c.setForeground(Color.BLACK);
            } else if (!selected) {
                c.setBackground(vm.isEditable(row, col) ? Color.WHITE : READ_ONLY);
                c.setForeground(Color.BLACK);
            }
            return c;
        }
    }

    private void choose(String nameOrFile) {
        try {
            vm.choose(nameOrFile);
            ctx.model().setJob(vm.applyTo(ctx.model().job()));
        } catch (CamInputException ex) {
            Dialogs.error(ctx.owner(), "Robot", ex.getMessage());
        }
        refresh();
    }

    /** A job that names another robot shows it; a bad name leaves the current one. */
    private void chooseQuietly(String nameOrFile) {
        try {
            vm.choose(nameOrFile);
        } catch (CamInputException ex) {
            return;
        }
        refresh();
    }

    private void openFile() {
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.ROBOT);
        if (fc.showOpenDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION) {
            choose(FileChoosers.chosen(fc).toAbsolutePath().toString());
        }
    }

    private void saveFile() {
        chosenFileForRobot("Save robot", FileChoosers.Kind.ROBOT, ".xml")
                .ifPresent(f -> saveAs(
                        f.getFileName().toString().contains(".") ? f : f.resolveSibling(f.getFileName() + ".xml")));
    }

    /**
     * The file the planner chooses to write the edited robot into, offered under the robot's name
     * with {@code suffix}; empty when the table has an error (said under {@code title}: nothing is
     * written from a wrong table) or when the planner cancels.
     */
    private Optional<Path> chosenFileForRobot(String title, FileChoosers.Kind kind, String suffix) {
        if (vm.edited().isEmpty()) {
            Dialogs.error(
                    ctx.owner(),
                    title,
                    "Correct the table first: " + vm.messages().get(0));
            return Optional.empty();
        }
        JFileChooser fc = FileChoosers.chooser(kind);
        fc.setSelectedFile(new java.io.File(vm.parameter(0) + suffix));
        return fc.showSaveDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION
                ? Optional.of(FileChoosers.chosen(fc))
                : Optional.empty();
    }

    /** Writes the edited robot into a file and makes the job name it (also used by the GUI test). */
    void saveAs(Path file) {
        commitTimer.stop();
        try {
            vm.save(file);
            ctx.model().setJob(vm.applyTo(ctx.model().job()));
        } catch (IOException ex) {
            Dialogs.error(ctx.owner(), "Save robot", "Cannot write " + file + ": " + ex.getMessage());
        }
        refreshLabels();
    }

    private void exportSymbolic() {
        chosenFileForRobot("Export symbolic FK", FileChoosers.Kind.TEXT, "-fk.txt")
                .ifPresent(this::exportSymbolicTo);
    }

    /** Writes the symbolic FK and Jacobian of the table's robot into a text file, in the background. */
    void exportSymbolicTo(Path file) {
        Robot r = vm.edited().orElseThrow();
        ctx.tasks()
                .start(
                        "Symbolic kinematics of " + r.name(),
                        progress -> {
                            org.fresa.io.AtomicFiles.writeString(file, RobotViewModel.symbolicExport(r));
                            return file;
                        },
                        f -> uses.setText("Wrote the symbolic kinematics of " + r.name() + " to " + f));
    }

    /** After an edit: show the problems now, write the robot into the job once typing pauses. */
    private void edited() {
        refreshLabels();
        if (vm.edited().isPresent()) {
            commitTimer.restart();
        } else {
            commitTimer.stop();
        }
    }

    private void commit() {
        if (vm.edited().isEmpty()) {
            return;
        }
        try {
            vm.keepIn(ctx.model().editedRobotsFolder());
            ctx.model().setJob(vm.applyTo(ctx.model().job()));
        } catch (IOException ex) {
            Dialogs.error(ctx.owner(), "Robot", "Cannot keep the edited robot: " + ex.getMessage());
        }
        if (paramFields.length > 0 && !paramFields[0].getText().trim().equals(vm.parameter(0))) {
            updating = true;
            try {
                paramFields[0].setText(vm.parameter(0));
            } finally {
                updating = false;
            }
        }
        refreshLabels();
        computeSymbolic();
    }

    private void refresh() {
        commitTimer.stop();
        updating = true;
        try {
            if (RobotViewModel.builtIns().contains(vm.choice())) {
                robots.setSelectedItem(vm.choice());
            }
        } finally {
            updating = false;
        }
        table.fireTableDataChanged();
        buildParameterFields();
        refreshLabels();
        computeSymbolic();
    }

    private void buildParameterFields() {
        paramPanel.removeAll();
        List<String> names = vm.parameterNames();
        paramFields = new JTextField[names.size()];
        GridBagConstraints c = new GridBagConstraints();
        c.insets = new Insets(1, 4, 1, 4);
        c.anchor = GridBagConstraints.WEST;
        int perRow = names.size() > 5 ? 4 : 3;
        for (int i = 0; i < names.size(); i++) {
            int index = i;
            JTextField f = new JTextField(vm.parameter(i), i == 0 ? 12 : 7);
            f.setName("robot-param-" + i);
            f.setToolTipText(Tooltips.robotParameter(names.get(i)));
            JLabel l = new JLabel(names.get(i) + ":");
            l.setLabelFor(f);
            TextChanges.onChange(f, () -> {
                if (!updating) {
                    vm.setParameter(index, f.getText());
                    table.fireTableDataChanged();
                    edited();
                }
            });
            paramFields[i] = f;
            int slot = i == 0 ? 0 : i - 1;
            c.gridy = i == 0 ? 0 : 1 + slot / perRow;
            c.gridx = i == 0 ? 0 : 2 * (slot % perRow);
            paramPanel.add(l, c);
            c.gridx++;
            c.gridwidth = i == 0 ? 3 : 1;
            paramPanel.add(f, c);
            c.gridwidth = 1;
        }
        paramPanel.revalidate();
        paramPanel.repaint();
    }

    private void refreshLabels() {
        List<String> m = vm.messages();
        messages.setText(m.isEmpty() ? " " : m.get(0) + (m.size() > 1 ? " (and " + (m.size() - 1) + " more)" : ""));
        for (int i = 0; i < paramFields.length; i++) {
            var p = vm.parameterProblem(i);
            paramFields[i].setBackground(p.isPresent() ? BAD : Color.WHITE);
            paramFields[i].setToolTipText(
                    p.orElse(Tooltips.robotParameter(vm.parameterNames().get(i))));
        }
        String c = vm.choice();
        boolean builtIn = RobotViewModel.builtIns().contains(c);
        String state = vm.edited().isEmpty()
                ? " (the table has problems: the job keeps the last valid robot)"
                : vm.isModified() ? " (edited, being kept...)" : "";
        uses.setText("The job uses " + (builtIn ? "the built-in " + c : c) + state);
        params.setText(String.join("\n", vm.parameters()));
        dh.repaint();
    }

    /** Derives the symbolic FK of the table's robot off the event thread (Symja starts in about a second). */
    private void computeSymbolic() {
        // only for the tab on screen: Symja's start and derivation take a core for a second or more,
        // which a job started in another tab (a job file opened sets the robot) should not compete
        // with; the tab derives it when it is shown
        if (vm.edited().isEmpty() || !panel.isShowing()) {
            return;
        }
        Robot r = vm.edited().get();
        if (r.equals(symbolicOf)) {
            return;
        }
        int generation = ++symbolicGeneration;
        symbolic.setText("Deriving the forward kinematics of " + r.name() + "...");
        // below the event thread's priority, as every background thread of the window
        SYMBOLIC.execute(new SwingWorker<String, Void>() {
            @Override
            protected String doInBackground() {
                return RobotViewModel.symbolic(r);
            }

            @Override
            protected void done() {
                if (generation != symbolicGeneration) {
                    return;
                }
                try {
                    symbolic.setText(get());
                    symbolicOf = r;
                } catch (ExecutionException ex) {
                    symbolic.setText("The symbolic forward kinematics failed: "
                            + ex.getCause().getMessage());
                } catch (InterruptedException ex) {
                    Thread.currentThread().interrupt();
                }
                symbolic.setCaretPosition(0);
            }
        });
    }
}
