package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.event.KeyEvent;
import java.util.IdentityHashMap;
import java.util.Map;
import javax.swing.BorderFactory;
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
import javax.swing.filechooser.FileNameExtensionFilter;
import javax.swing.table.DefaultTableModel;
import org.fresa.kin.Robot;
import org.fresa.model.CamInputException;

/**
 * The Robot tab: choose a built-in robot or open a robot file, read its DH table and parameters,
 * and its symbolic forward kinematics (computed in the background, once per robot).
 */
final class RobotTab implements ModuleTab {

    private final AppContext ctx;
    private final RobotViewModel vm = new RobotViewModel();
    private final JPanel panel = new JPanel(new BorderLayout());
    private final JComboBox<String> robots = new JComboBox<>(RobotViewModel.builtIns().toArray(String[]::new));
    private final DefaultTableModel table = new DefaultTableModel(RobotViewModel.COLUMNS, 0) {
        private static final long serialVersionUID = 1L;

        @Override
        public boolean isCellEditable(int row, int column) {
            return false;
        }
    };
    private final JTextArea params = new JTextArea(5, 40);
    private final JTextArea symbolic = new JTextArea(12, 60);
    private final Map<Robot, String> symbolicCache = new IdentityHashMap<>();
    private boolean updating;

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
        JButton open = new JButton("Open robot file...");
        open.setName("robot-open");
        open.setMnemonic(KeyEvent.VK_O);
        open.addActionListener(e -> openFile());
        JButton fk = new JButton("Symbolic FK");
        fk.setName("robot-symbolic");
        fk.setMnemonic(KeyEvent.VK_K);
        fk.addActionListener(e -> computeSymbolic());
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(robotLabel);
        top.add(robots);
        top.add(open);
        top.add(fk);

        JTable dh = new JTable(table);
        dh.setName("robot-dh");
        dh.setFillsViewportHeight(true);
        JLabel dhLabel = new JLabel("Denavit-Hartenberg table (A = Rz(theta) Tz(d) Tx(a) Rx(alpha))");
        dhLabel.setDisplayedMnemonic(KeyEvent.VK_D);
        dhLabel.setLabelFor(dh);
        params.setEditable(false);
        params.setName("robot-parameters");
        JLabel paramLabel = new JLabel("Parameters");
        paramLabel.setDisplayedMnemonic(KeyEvent.VK_P);
        paramLabel.setLabelFor(params);
        JPanel upper = new JPanel(new BorderLayout());
        upper.add(dhLabel, BorderLayout.NORTH);
        JScrollPane dhScroll = new JScrollPane(dh);
        dhScroll.setPreferredSize(new java.awt.Dimension(700, 170));
        upper.add(dhScroll, BorderLayout.CENTER);
        JPanel paramPanel = new JPanel(new BorderLayout());
        paramPanel.add(paramLabel, BorderLayout.NORTH);
        paramPanel.add(params, BorderLayout.CENTER);
        upper.add(paramPanel, BorderLayout.SOUTH);

        symbolic.setEditable(false);
        symbolic.setName("robot-fk");
        symbolic.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        JLabel symLabel = new JLabel("Symbolic forward kinematics (Symja)");
        symLabel.setDisplayedMnemonic(KeyEvent.VK_S);
        symLabel.setLabelFor(symbolic);
        JPanel lower = new JPanel(new BorderLayout());
        lower.add(symLabel, BorderLayout.NORTH);
        lower.add(new JScrollPane(symbolic), BorderLayout.CENTER);

        JSplitPane split = new JSplitPane(JSplitPane.VERTICAL_SPLIT, upper, lower);
        split.setResizeWeight(0.5);
        panel.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        panel.add(top, BorderLayout.NORTH);
        panel.add(split, BorderLayout.CENTER);
        ctx.model().addListener(e -> {
            if (MainViewModel.JOB.equals(e.getPropertyName())) {
                vm.fromJob(ctx.model().job()).ifPresent(this::chooseQuietly);
            }
        });
        refresh();
    }

    @Override
    public String title() {
        return "Robot";
    }

    @Override
    public JComponent component() {
        return panel;
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
        JFileChooser fc = new JFileChooser();
        fc.setFileFilter(new FileNameExtensionFilter("Robot files (*.xml)", "xml"));
        if (fc.showOpenDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION) {
            choose(fc.getSelectedFile().toPath().toAbsolutePath().toString());
        }
    }

    private void refresh() {
        updating = true;
        try {
            String name = vm.robot().name();
            if (RobotViewModel.builtIns().contains(vm.choice())) {
                robots.setSelectedItem(name);
            }
        } finally {
            updating = false;
        }
        table.setRowCount(0);
        for (String[] row : vm.dhRows()) {
            table.addRow(row);
        }
        params.setText(String.join("\n", vm.parameters()));
        String cached = symbolicCache.get(vm.robot());
        symbolic.setText(cached != null ? cached : "Press Symbolic FK (Alt+K) to derive the expressions (takes a second).");
        symbolic.setCaretPosition(0);
    }

    private void computeSymbolic() {
        Robot r = vm.robot();
        if (symbolicCache.containsKey(r)) {
            refresh();
            return;
        }
        symbolic.setText("Deriving the forward kinematics of " + r.name() + "...");
        ctx.tasks().start("Symbolic kinematics of " + r.name(), progress -> RobotViewModel.symbolic(r), text -> {
            symbolicCache.put(r, text);
            if (vm.robot() == r) {
                symbolic.setText(text);
                symbolic.setCaretPosition(0);
            }
        });
    }
}
