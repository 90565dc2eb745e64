package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.Font;
import java.nio.file.Path;
import java.util.Optional;
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
import javax.swing.filechooser.FileNameExtensionFilter;
import org.fresa.job.CuttingService;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.model.CamInputException;

/** Sheet cutting: open a DXF, set kerf, process and leads, cut, see the plan and the program. */
final class CuttingTab implements ModuleTab {

    private final AppContext ctx;
    private final CuttingViewModel vm = new CuttingViewModel();
    private final JPanel panel = new JPanel(new BorderLayout());
    private final PlotPanel plot = new PlotPanel();
    private final JTextArea program = new JTextArea();
    private final JLabel totals = new JLabel("No drawing cut yet.");
    private final JTextField file = new JTextField(24);

    CuttingTab(AppContext ctx) {
        this.ctx = ctx;
        JPanel form = new JPanel(new FlowLayout(FlowLayout.LEFT));
        JButton open = new JButton("Open DXF...");
        open.setMnemonic('O');
        open.addActionListener(e -> choose());
        file.setEditable(false);
        JTextField kerf = field(form, "Kerf mm:", 'K', "2");
        JComboBox<String> process = new JComboBox<>(new String[] {"plasma", "laser", "waterjet"});
        JLabel pl = new JLabel("Process:");
        pl.setDisplayedMnemonic('P');
        pl.setLabelFor(process);
        JTextField leadIn = field(form, "Lead-in mm:", 'I', "3");
        JTextField leadOut = field(form, "Lead-out mm:", 'U', "1");
        JComboBox<String> lead = new JComboBox<>(new String[] {"arc", "line"});
        JComboBox<String> post = new JComboBox<>(new String[] {"linuxcnc", "iso", "fanuc", "840d"});
        JCheckBox paper = new JCheckBox("Paper mode");
        paper.setMnemonic('M');
        JButton cut = new JButton("Cut");
        cut.setMnemonic('C');
        cut.addActionListener(e -> {
            vm.setKerfMm(kerf.getText());
            vm.setProcess((String) process.getSelectedItem());
            vm.setLeadInMm(leadIn.getText());
            vm.setLeadOutMm(leadOut.getText());
            vm.setLead((String) lead.getSelectedItem());
            vm.setPost((String) post.getSelectedItem());
            vm.setPaperMode(paper.isSelected());
            run();
        });
        JPanel top = new JPanel(new FlowLayout(FlowLayout.LEFT));
        top.add(open);
        top.add(file);
        top.add(pl);
        top.add(process);
        top.add(new JLabel("Lead:"));
        top.add(lead);
        top.add(new JLabel("Post:"));
        top.add(post);
        top.add(paper);
        top.add(cut);
        JPanel north = new JPanel(new BorderLayout());
        north.add(top, BorderLayout.NORTH);
        north.add(form, BorderLayout.CENTER);
        program.setEditable(false);
        program.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        program.setName("cutting-program");
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, plot, new JScrollPane(program));
        split.setResizeWeight(0.7);
        panel.add(north, BorderLayout.NORTH);
        panel.add(split, BorderLayout.CENTER);
        panel.add(totals, BorderLayout.SOUTH);
    }

    private static JTextField field(JPanel form, String label, char mnemonic, String value) {
        JLabel l = new JLabel(label);
        JTextField f = new JTextField(value, 5);
        l.setDisplayedMnemonic(mnemonic);
        l.setLabelFor(f);
        form.add(l);
        form.add(f);
        return f;
    }

    private void choose() {
        JFileChooser ch = new JFileChooser();
        ch.setFileFilter(new FileNameExtensionFilter("DXF drawings", "dxf"));
        if (ch.showOpenDialog(ctx.owner()) == JFileChooser.APPROVE_OPTION) {
            Path p = ch.getSelectedFile().toPath();
            vm.setDrawing(p);
            file.setText(p.getFileName().toString());
        }
    }

    private void run() {
        CuttingSettings s;
        try {
            s = vm.settings();
        } catch (CamInputException e) {
            totals.setText(e.getMessage());
            return;
        }
        ctx.tasks().start("Cutting", progress -> CuttingService.compute(s, progress), r -> {
            vm.setResult(r);
            plot.show(vm.scene());
            program.setText(vm.program());
            program.setCaretPosition(0);
            totals.setText(vm.totals());
        });
    }

    @Override
    public String title() {
        return "Cutting";
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
