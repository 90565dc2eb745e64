package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Point;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.StringSelection;
import java.awt.datatransfer.Transferable;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.AbstractAction;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTable;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import javax.swing.ListSelectionModel;
import javax.swing.TransferHandler;
import javax.swing.table.AbstractTableModel;
import org.fresa.chart.PlotScene;
import org.fresa.geom.Vec2;
import org.fresa.job.JobSettings;
import org.fresa.sole.Foot;

/**
 * The Sole tab: the DESCOM figure library with a preview, dragged (or placed with Place) onto
 * the outline plot; the placed figure selected on the plot or in the Figure list, dragged or
 * nudged with the arrow keys (1 mm, Shift 10 mm), removed with Delete; its parameters edited in
 * a table; the job's size and foot; Generate writes the programs of the edited job.
 */
final class SoleTab extends PlotTab {

    private final SoleViewModel vm = new SoleViewModel();
    private final AppContext ctx;
    private final PlotPanel preview = new PlotPanel();
    private final WarningsPanel problems = new WarningsPanel("sole-problems", 3);
    private final JList<String> library;
    private final JTextArea info = new JTextArea(9, 22);
    private final JComboBox<String> sizes = new JComboBox<>();
    private final JComboBox<Foot> feet = new JComboBox<>(Foot.values());
    private final JComboBox<String> placed = new JComboBox<>();
    private final ParameterTable parameters = new ParameterTable();
    private final JTextField outFolder =
            new JTextField(Path.of("sole-out").toAbsolutePath().toString(), 22);
    private final JLabel status = new JLabel(" ");
    private boolean updatingPlaced;
    private Vec2 dragFrom;

    SoleTab(AppContext ctx) {
        super("Sole");
        this.ctx = ctx;
        library = new JList<>(vm.macros().toArray(new String[0]));
        library.setName("sole-library");
        library.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        library.addListSelectionListener(e -> {
            if (!e.getValueIsAdjusting() && library.getSelectedValue() != null) {
                vm.selectMacro(library.getSelectedValue());
                showFigure();
            }
        });
        library.setDragEnabled(true);
        library.setTransferHandler(new TransferHandler() {
            private static final long serialVersionUID = 1L;

            @Override
            public int getSourceActions(JComponent c) {
                return COPY;
            }

            @Override
            protected Transferable createTransferable(JComponent c) {
                return new StringSelection(library.getSelectedValue());
            }
        });
        JLabel libLabel = new JLabel("Figures (drag onto the sole)");
        libLabel.setDisplayedMnemonic(KeyEvent.VK_F);
        libLabel.setLabelFor(library);
        info.setEditable(false);
        info.setName("sole-figure-info");
        preview.setPreferredSize(new Dimension(260, 200));
        JButton place = Buttons.of("Place", "sole-place", KeyEvent.VK_P, () -> placeAt(plotCentre()));
        place.setToolTipText("Places the library figure at the middle of the plot; then move it with the arrow keys");
        JPanel lib = new JPanel(new BorderLayout(4, 4));
        lib.add(new JScrollPane(library), BorderLayout.WEST);
        JPanel infoPane = new JPanel(new BorderLayout(2, 2));
        infoPane.add(new JScrollPane(info), BorderLayout.CENTER);
        infoPane.add(place, BorderLayout.SOUTH);
        lib.add(infoPane, BorderLayout.CENTER);
        lib.add(preview, BorderLayout.SOUTH);

        JLabel placedLabel = labelFor(placed, "sole-designs", "Figure", KeyEvent.VK_G);
        placed.addActionListener(e -> {
            if (!updatingPlaced) {
                vm.select(placed.getSelectedIndex() - 1 < -1 ? -1 : placed.getSelectedIndex() - 1);
                refresh(false);
            }
        });
        JLabel paramLabel = new JLabel("Parameters");
        paramLabel.setDisplayedMnemonic(KeyEvent.VK_A);
        paramLabel.setLabelFor(parameters.table);
        JPanel selection = new JPanel(new BorderLayout(4, 4));
        JPanel selTop = new JPanel(new BorderLayout(4, 4));
        selTop.add(placedLabel, BorderLayout.WEST);
        selTop.add(placed, BorderLayout.CENTER);
        selTop.add(paramLabel, BorderLayout.SOUTH);
        selection.add(selTop, BorderLayout.NORTH);
        JScrollPane tableScroll = new JScrollPane(parameters.table);
        tableScroll.setPreferredSize(new Dimension(260, 170));
        selection.add(tableScroll, BorderLayout.CENTER);

        JPanel left = new JPanel(new BorderLayout(4, 8));
        left.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        left.add(libLabel, BorderLayout.NORTH);
        left.add(lib, BorderLayout.CENTER);
        left.add(selection, BorderLayout.SOUTH);

        JLabel sizeLabel = labelFor(sizes, "sole-size", "Size", KeyEvent.VK_Z);
        JLabel footLabel = labelFor(feet, "sole-foot", "Foot", KeyEvent.VK_T);
        JButton load = Buttons.of("Load job", "sole-load", KeyEvent.VK_L, () -> loadJob());
        JButton show = Buttons.of("Show", null, KeyEvent.VK_S, () -> showSole());
        JButton block = Buttons.of("Mould block", "sole-block", KeyEvent.VK_B, () -> showBlock());
        block.setToolTipText("Shows the size's left and right sole where the mould block's equations place them");
        JPanel top = Buttons.row(load, sizeLabel, sizes, footLabel, feet, show, block);
        JLabel outLabel = labelFor(outFolder, "sole-out", "Output folder", KeyEvent.VK_O);
        JButton choose = Buttons.of("...", null, 0, () -> chooseFolder());
        choose.setToolTipText("Choose the output folder");
        JButton generate = Buttons.of("Generate", "sole-generate", KeyEvent.VK_E, () -> generate());
        status.setName("sole-status");
        JPanel bottom = Buttons.row(outLabel, outFolder, choose, generate, status);
        JPanel right = new JPanel(new BorderLayout());
        right.add(top, BorderLayout.NORTH);
        right.add(plot, BorderLayout.CENTER);
        JPanel south = new JPanel(new BorderLayout());
        south.add(bottom, BorderLayout.NORTH);
        south.add(problems, BorderLayout.CENTER);
        right.add(south, BorderLayout.SOUTH);
        panel.add(new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left, right), BorderLayout.CENTER);
        installPlotEditing();
        ctx.model().addListener(e -> {
            if (MainViewModel.JOB.equals(e.getPropertyName())
                    && !vm.job().equals(Optional.of(ctx.model().job()))) {
                // another job was opened or edited elsewhere: never edit the old one on top of it
                jobReplaced(ctx.model().job());
            }
        });
        library.setSelectedIndex(vm.macros().indexOf("SUB4"));
    }

    /** Names the field and returns its label, whose mnemonic moves the focus to the field. */
    private static JLabel labelFor(JComponent field, String name, String text, int mnemonic) {
        field.setName(name);
        JLabel label = new JLabel(text);
        label.setDisplayedMnemonic(mnemonic);
        label.setLabelFor(field);
        return label;
    }

    /** Drops from the library, press-drag-release to move, keys to nudge and delete. */
    private void installPlotEditing() {
        JComponent chart = plot.chartComponent();
        chart.setTransferHandler(new TransferHandler() {
            private static final long serialVersionUID = 1L;

            @Override
            public boolean canImport(TransferSupport s) {
                return s.isDataFlavorSupported(DataFlavor.stringFlavor);
            }

            @Override
            public boolean importData(TransferSupport s) {
                try {
                    String m = (String) s.getTransferable().getTransferData(DataFlavor.stringFlavor);
                    if (!vm.macros().contains(m)) {
                        return false;
                    }
                    vm.selectMacro(m);
                    Point p = s.isDrop() ? s.getDropLocation().getDropPoint() : null;
                    placeAt(p == null ? plotCentre() : plot.toPlotMm(p));
                    return true;
                } catch (java.awt.datatransfer.UnsupportedFlavorException | java.io.IOException e) {
                    return false;
                }
            }
        });
        chart.addMouseListener(new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                if (vm.job().isEmpty() || e.isControlDown() || e.getButton() != MouseEvent.BUTTON1) {
                    return;
                }
                chart.requestFocusInWindow();
                Vec2 at = plot.toPlotMm(e.getPoint());
                if (vm.selectAt(at)) {
                    dragFrom = at;
                    plot.setDragZoom(false);
                } else {
                    dragFrom = null;
                }
                refresh(false);
            }

            @Override
            public void mouseReleased(MouseEvent e) {
                if (dragFrom == null) {
                    return;
                }
                plot.setDragZoom(true);
                Vec2 to = plot.toPlotMm(e.getPoint());
                Vec2 d = vm.deltaToJobFrame(to.minus(dragFrom));
                dragFrom = null;
                if (Math.hypot(d.x(), d.y()) > 0.05) {
                    edited(vm.moveSelectedBy(d.x(), d.y()));
                }
            }
        });
        bind(chart, "LEFT", -1, 0);
        bind(chart, "RIGHT", 1, 0);
        bind(chart, "UP", 0, 1);
        bind(chart, "DOWN", 0, -1);
        bind(chart, "shift LEFT", -10, 0);
        bind(chart, "shift RIGHT", 10, 0);
        bind(chart, "shift UP", 0, 10);
        bind(chart, "shift DOWN", 0, -10);
        chart.getInputMap(JComponent.WHEN_FOCUSED).put(KeyStroke.getKeyStroke("DELETE"), "sole-delete");
        chart.getActionMap().put("sole-delete", new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                edited(vm.deleteSelected());
            }
        });
    }

    /** Arrow keys move by millimetres of the job's frame; on the left foot x runs mirrored. */
    private void bind(JComponent c, String key, double dxMm, double dyMm) {
        String name = "sole-nudge " + key;
        c.getInputMap(JComponent.WHEN_FOCUSED).put(KeyStroke.getKeyStroke(key), name);
        c.getActionMap().put(name, new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                double sx = vm.foot() == Foot.LEFT ? -1 : 1;
                edited(vm.moveSelectedBy(sx * dxMm, dyMm));
            }
        });
    }

    private Vec2 plotCentre() {
        return plot.scene().bounds().map(b -> b.center()).orElse(Vec2.ZERO);
    }

    private void placeAt(Vec2 plotMm) {
        edited(vm.place(plotMm));
        plot.chartComponent().requestFocusInWindow();
    }

    /** After an edit: the job goes to the window (so Save saves it) and the plot is redrawn. */
    private void edited(Optional<String> why) {
        if (why.isPresent()) {
            status.setText(why.get());
            return;
        }
        vm.job().ifPresent(j -> ctx.model().setJob(j));
        refresh(true);
    }

    private void refresh(boolean jobChanged) {
        if (jobChanged || placed.getItemCount() != vm.designs().size() + 1) {
            updatingPlaced = true;
            placed.removeAllItems();
            placed.addItem("(none)");
            for (JobSettings.SoleDesign d : vm.designs()) {
                placed.addItem(d.name());
            }
            updatingPlaced = false;
        }
        updatingPlaced = true;
        placed.setSelectedIndex(vm.selected() + 1);
        updatingPlaced = false;
        parameters.reload();
        if (vm.selected() >= 0) {
            Vec2 at = vm.position(vm.selected());
            status.setText(String.format(
                    java.util.Locale.ROOT,
                    "%s at x %.1f mm, y %.1f mm (job frame)",
                    vm.designs().get(vm.selected()).name(),
                    at.x(),
                    at.y()));
        }
        if (!vm.sizes().isEmpty()) {
            plot.update(vm.scene());
        }
    }

    private void jobReplaced(org.fresa.job.Job j) {
        vm.load(org.fresa.job.Job.empty(org.fresa.job.JobTask.SOLE));
        sizes.removeAllItems();
        refresh(true);
        if (j.sole().isPresent()) {
            loadJob();
        } else {
            status.setText("Load a sole job");
            plot.show(PlotScene.empty("No sole job"));
        }
    }

    private void showFigure() {
        info.setText(vm.parametersText());
        preview.show(vm.preview());
    }

    private void loadJob() {
        ctx.tasks()
                .start(
                        "Planning the sole",
                        pm -> {
                            vm.load(ctx.model().job());
                            return vm.sizes();
                        },
                        list -> {
                            sizes.removeAllItems();
                            list.forEach(sizes::addItem);
                            if (!list.isEmpty()) {
                                sizes.setSelectedItem(vm.size());
                            }
                            status.setText(vm.problem().isEmpty() ? list.size() + " sizes" : vm.problem());
                            refresh(true);
                            if (vm.problem().isEmpty()) {
                                showSole();
                            } else {
                                plot.show(PlotScene.empty(vm.problem()));
                            }
                        });
    }

    private void showSole() {
        if (sizes.getSelectedItem() == null) {
            status.setText("Load a sole job first");
            return;
        }
        vm.selectSize((String) sizes.getSelectedItem());
        vm.selectFoot((Foot) feet.getSelectedItem());
        ctx.tasks().start("Tread of size " + vm.size(), pm -> new Shown(vm.scene(), vm.sizeProblem()), shown -> {
            plot.show(shown.scene());
            // what Generate would refuse of this size, before Generate
            shown.problem().ifPresent(status::setText);
        });
    }

    private void showBlock() {
        if (sizes.getSelectedItem() == null) {
            status.setText("Load a sole job first");
            return;
        }
        vm.selectSize((String) sizes.getSelectedItem());
        ctx.tasks().start("Pair of size " + vm.size() + " in the mould block", pm -> vm.pairScene(), plot::show);
    }

    private void chooseFolder() {
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.FOLDER);
        fc.setDialogTitle("Output folder of the sole programs");
        if (fc.showSaveDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION) {
            outFolder.setText(FileChoosers.chosen(fc).toAbsolutePath().toString());
        }
    }

    private void generate() {
        String f = outFolder.getText().trim();
        if (f.isEmpty()) {
            status.setText("Choose an output folder first");
            return;
        }
        Path folder = Path.of(f);
        ctx.tasks().start("Generating the sole programs", pm -> vm.generate(folder, pm), outcome -> {
            status.setText(outcome.files().size() + " files written to " + folder
                    + (outcome.problems().isEmpty()
                            ? ""
                            : "; " + outcome.problems().size() + " problems listed below"));
            problems.show(WarningList.of(outcome.problems()));
        });
    }

    /** The selected figure's parameters: name, unit, value (editable, checked by the view model). */
    private final class ParameterTable extends AbstractTableModel {
        private static final long serialVersionUID = 1L;
        private final JTable table = new JTable(this);
        private transient java.util.List<SoleViewModel.Parameter> rows = java.util.List.of();

        ParameterTable() {
            table.setName("sole-parameters");
            table.setFillsViewportHeight(true);
            table.putClientProperty("terminateEditOnFocusLost", Boolean.TRUE);
        }

        void reload() {
            rows = vm.parameters();
            fireTableDataChanged();
        }

        @Override
        public int getRowCount() {
            return rows.size();
        }

        @Override
        public int getColumnCount() {
            return 3;
        }

        @Override
        public String getColumnName(int c) {
            return new String[] {"Name", "Unit", "Value"}[c];
        }

        @Override
        public Object getValueAt(int r, int c) {
            SoleViewModel.Parameter p = rows.get(r);
            return c == 0 ? p.name() : c == 1 ? p.unit() : p.value();
        }

        @Override
        public boolean isCellEditable(int r, int c) {
            return c == 2;
        }

        @Override
        public void setValueAt(Object value, int r, int c) {
            Optional<String> why = vm.setParameter(rows.get(r).name(), String.valueOf(value));
            if (why.isPresent()) {
                status.setText(why.get());
                fireTableRowsUpdated(r, r);
            } else {
                edited(why);
            }
        }
    }

    /** A size's plot and what Generate would refuse of it, found off the event thread. */
    private record Shown(org.fresa.chart.PlotScene scene, Optional<String> problem) {}
}
