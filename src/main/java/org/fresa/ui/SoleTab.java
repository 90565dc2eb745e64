package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.event.KeyEvent;
import java.util.Optional;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTextArea;
import javax.swing.ListSelectionModel;
import org.fresa.chart.PlotScene;
import org.fresa.sole.Foot;

/**
 * The Sole tab: the DESCOM figure library with a preview and the parameters of each macro, the
 * job's size and foot, and the plot of the outline and clipped tread of that size and foot.
 */
final class SoleTab implements ModuleTab {

    private final SoleViewModel vm = new SoleViewModel();
    private final AppContext ctx;
    private final JPanel panel = new JPanel(new BorderLayout());
    private final PlotPanel plot = new PlotPanel();
    private final PlotPanel preview = new PlotPanel();
    private final JTextArea params = new JTextArea(12, 22);
    private final JComboBox<String> sizes = new JComboBox<>();
    private final JComboBox<Foot> feet = new JComboBox<>(Foot.values());
    private final JLabel status = new JLabel(" ");

    SoleTab(AppContext ctx) {
        this.ctx = ctx;
        JList<String> library = new JList<>(vm.macros().toArray(new String[0]));
        library.setName("sole-library");
        library.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        library.addListSelectionListener(e -> {
            if (!e.getValueIsAdjusting() && library.getSelectedValue() != null) {
                vm.selectMacro(library.getSelectedValue());
                showFigure();
            }
        });
        JLabel libLabel = new JLabel("Figures");
        libLabel.setDisplayedMnemonic(KeyEvent.VK_F);
        libLabel.setLabelFor(library);
        params.setEditable(false);
        params.setName("sole-parameters");
        preview.setPreferredSize(new Dimension(260, 220));
        JPanel left = new JPanel(new BorderLayout(4, 4));
        left.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        left.add(libLabel, BorderLayout.NORTH);
        JPanel lib = new JPanel(new BorderLayout(4, 4));
        lib.add(new JScrollPane(library), BorderLayout.WEST);
        lib.add(new JScrollPane(params), BorderLayout.CENTER);
        left.add(lib, BorderLayout.CENTER);
        left.add(preview, BorderLayout.SOUTH);

        JLabel sizeLabel = new JLabel("Size");
        sizeLabel.setDisplayedMnemonic(KeyEvent.VK_Z);
        sizeLabel.setLabelFor(sizes);
        sizes.setName("sole-size");
        JLabel footLabel = new JLabel("Foot");
        footLabel.setDisplayedMnemonic(KeyEvent.VK_T);
        footLabel.setLabelFor(feet);
        feet.setName("sole-foot");
        JButton load = new JButton("Load job");
        load.setMnemonic(KeyEvent.VK_L);
        load.addActionListener(e -> loadJob());
        JButton show = new JButton("Show");
        show.setMnemonic(KeyEvent.VK_S);
        show.addActionListener(e -> showSole());
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(load);
        top.add(sizeLabel);
        top.add(sizes);
        top.add(footLabel);
        top.add(feet);
        top.add(show);
        top.add(status);
        JPanel right = new JPanel(new BorderLayout());
        right.add(top, BorderLayout.NORTH);
        right.add(plot, BorderLayout.CENTER);
        panel.add(new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left, right), BorderLayout.CENTER);
        library.setSelectedIndex(vm.macros().indexOf("SUB1A"));
    }

    private void showFigure() {
        params.setText(vm.parametersText());
        preview.show(vm.preview());
    }

    private void loadJob() {
        ctx.tasks().start("Planning the sole", pm -> {
            vm.load(ctx.model().job());
            return vm.sizes();
        }, list -> {
            sizes.removeAllItems();
            list.forEach(sizes::addItem);
            if (!list.isEmpty()) {
                sizes.setSelectedItem(vm.size());
            }
            status.setText(vm.problem().isEmpty() ? list.size() + " sizes" : vm.problem());
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
        ctx.tasks().start("Tread of size " + vm.size(), pm -> vm.scene(), plot::show);
    }

    @Override
    public String title() {
        return "Sole";
    }

    @Override
    public JComponent component() {
        return panel;
    }

    @Override
    public Optional<PlotPanel> plot() {
        return Optional.of(plot);
    }
}
