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
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.JTree;
import javax.swing.TransferHandler;
import javax.swing.filechooser.FileNameExtensionFilter;
import javax.swing.tree.DefaultMutableTreeNode;
import javax.swing.tree.DefaultTreeModel;
import javax.swing.tree.TreePath;
import org.fresa.job.JobSettings;
import org.fresa.job.StepNcService;

/**
 * The STEP-NC tab: open a Part 21 file (button or drag and drop), browse project > workplans >
 * workingsteps, read the selected workingstep's data with units, see the block and the feature.
 * Reading runs in the background; all state lives in {@link StepNcViewModel}.
 */
final class StepNcTab implements ModuleTab {

    private final AppContext ctx;
    private final StepNcViewModel vm = new StepNcViewModel();
    private final JPanel panel = new JPanel(new BorderLayout());
    private final JLabel fileLabel = new JLabel("No file read. Open a STEP-NC file or drop one here.");
    private final JTree tree = new JTree(new DefaultTreeModel(new DefaultMutableTreeNode("No file")));
    private final JTextArea details = new JTextArea(14, 40);
    private final PlotPanel plot = new PlotPanel();
    // the file shown, and the last one asked for (a failed read is not retried on every job change)
    private Path loadedFile;
    private Path requestedFile;

    StepNcTab(AppContext ctx) {
        this.ctx = ctx;
        JButton open = new JButton("Open STEP-NC file...");
        open.setMnemonic(KeyEvent.VK_O);
        open.setName("stepnc-open");
        open.addActionListener(e -> choose());
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(open);
        top.add(fileLabel);

        tree.setName("stepnc-tree");
        tree.setRootVisible(true);
        tree.addTreeSelectionListener(e -> selectionChanged());
        JLabel treeLabel = new JLabel("Workplans and workingsteps");
        treeLabel.setDisplayedMnemonic(KeyEvent.VK_W);
        treeLabel.setLabelFor(tree);
        JPanel left = new JPanel(new BorderLayout());
        left.add(treeLabel, BorderLayout.NORTH);
        left.add(new JScrollPane(tree), BorderLayout.CENTER);

        details.setEditable(false);
        details.setName("stepnc-details");
        details.setLineWrap(true);
        details.setWrapStyleWord(true);
        JLabel detailsLabel = new JLabel("Selected workingstep");
        detailsLabel.setDisplayedMnemonic(KeyEvent.VK_S);
        detailsLabel.setLabelFor(details);
        JPanel right = new JPanel(new BorderLayout());
        right.add(detailsLabel, BorderLayout.NORTH);
        JSplitPane rightSplit = new JSplitPane(JSplitPane.VERTICAL_SPLIT, new JScrollPane(details), plot);
        rightSplit.setResizeWeight(0.4);
        right.add(rightSplit, BorderLayout.CENTER);

        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left, right);
        split.setResizeWeight(0.35);
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

    @Override
    public String title() {
        return "STEP-NC";
    }

    @Override
    public JComponent component() {
        return panel;
    }

    @Override
    public Optional<PlotPanel> plot() {
        return Optional.of(plot);
    }

    private void choose() {
        JFileChooser fc = new JFileChooser(ctx.model().job().stepnc().map(s -> s.file().getParent())
                .map(Path::toFile).orElse(null));
        fc.setFileFilter(new FileNameExtensionFilter("STEP-NC Part 21 (*.stp, *.step, *.p21)", "stp", "step", "p21"));
        if (fc.showOpenDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION) {
            open(fc.getSelectedFile().toPath());
        }
    }

    /** A job opened with a STEP-NC file shows that file here. */
    private void jobChanged() {
        ctx.model().job().stepnc().map(JobSettings.StepNcSettings::file)
                .filter(f -> !f.equals(loadedFile) && !f.equals(requestedFile))
                .ifPresent(this::open);
    }

    void open(Path file) {
        requestedFile = file;
        ctx.tasks().start("Reading " + file.getFileName(), progress -> StepNcService.read(file, progress), program -> {
            vm.load(program);
            loadedFile = file;
            String post = ctx.model().job().stepnc().map(JobSettings.StepNcSettings::post).orElse("linuxcnc");
            ctx.model().setJob(ctx.model().job().withStepnc(new JobSettings.StepNcSettings(file, post)));
            fileLabel.setText(file.getFileName() + ": " + program.workingsteps().size() + " workingsteps, "
                    + program.skipped().size() + " skipped, " + program.unknownEntities().size()
                    + " entity types not interpreted");
            refresh();
        });
    }

    private void refresh() {
        DefaultMutableTreeNode root = vm.tree().map(StepNcTab::toSwing)
                .orElse(new DefaultMutableTreeNode("No file"));
        tree.setModel(new DefaultTreeModel(root));
        for (int i = 0; i < Math.min(tree.getRowCount(), 200); i++) {
            tree.expandRow(i);
        }
        showSelection();
    }

    private static DefaultMutableTreeNode toSwing(StepNcViewModel.Node n) {
        DefaultMutableTreeNode d = new DefaultMutableTreeNode(n);
        for (StepNcViewModel.Node c : n.children()) {
            d.add(toSwing(c));
        }
        return d;
    }

    private void selectionChanged() {
        TreePath path = tree.getSelectionPath();
        if (path != null && path.getLastPathComponent() instanceof DefaultMutableTreeNode d
                && d.getUserObject() instanceof StepNcViewModel.Node n) {
            vm.select(n.workingstep());
            showSelection();
        }
    }

    private void showSelection() {
        details.setText(String.join("\n", vm.details()));
        details.setCaretPosition(0);
        plot.show(vm.plot());
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
