package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.GridLayout;
import java.nio.file.Path;
import java.util.Optional;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import org.fresa.job.JobSettings.PocketSettings;

/** The Pocket tab: contour file, technology, the recognition tree, the toolpath plot and the NC text. */
final class PocketTab implements ModuleTab {

    private final AppContext ctx;
    private final PocketViewModel model = new PocketViewModel();
    private final JPanel panel = new JPanel(new BorderLayout());
    private final PlotPanel plot = new PlotPanel();
    private final JTextArea report = new JTextArea(12, 40);
    private final JTextArea nc = new JTextArea(12, 40);
    private final JTextField contour = new JTextField(24);
    private final JTextField[] tech = new JTextField[9];
    private final JComboBox<String> post = new JComboBox<>(new String[] {"7m-compat", "7m", "linuxcnc"});
    private final JComboBox<String> direction = new JComboBox<>(PocketSettings.DIRECTIONS.toArray(new String[0]));
    private final JLabel status = new JLabel(" ");

    PocketTab(AppContext ctx) {
        this.ctx = ctx;
        String[] names = {"Tool diameter (mm)", "Cut fraction", "Finish fraction", "Z top (mm)", "Z bottom (mm)",
            "Max depth per pass (mm)", "Spindle (rpm)", "Feed (mm/min)", "Finish feed (mm/min)"};
        PocketSettings s = model.settings();
        double[] values = {s.toolDiameterMm(), s.cutFraction(), s.finishFraction(), s.zTopMm(), s.zBottomMm(),
            s.maxDepthPerPassMm(), s.spindleRpm(), s.feedMmPerMin(), s.finishFeedMmPerMin()};
        JPanel form = new JPanel(new GridLayout(0, 2, 4, 4));
        JLabel cl = new JLabel("Contour (.dad, .contour)");
        cl.setLabelFor(contour);
        cl.setDisplayedMnemonic('o');
        contour.setText(s.contour().toString());
        contour.setName("pocket-contour");
        form.add(cl);
        JPanel file = new JPanel(new BorderLayout());
        file.add(contour, BorderLayout.CENTER);
        JButton browse = new JButton("...");
        browse.getAccessibleContext().setAccessibleName("Choose contour file");
        browse.addActionListener(e -> {
            JFileChooser ch = FileChoosers.chooser(FileChoosers.Kind.POCKET_CONTOUR);
            if (ch.showOpenDialog(panel) == JFileChooser.APPROVE_OPTION) {
                contour.setText(FileChoosers.chosen(ch).toString());
            }
        });
        file.add(browse, BorderLayout.EAST);
        form.add(file);
        for (int i = 0; i < names.length; i++) {
            tech[i] = new JTextField(Double.toString(values[i]), 8);
            JLabel l = new JLabel(names[i]);
            l.setLabelFor(tech[i]);
            form.add(l);
            form.add(tech[i]);
        }
        JLabel pl = new JLabel("Post");
        pl.setLabelFor(post);
        pl.setDisplayedMnemonic('P');
        form.add(pl);
        form.add(post);
        JLabel dl = new JLabel("Direction (not 7m-compat)");
        dl.setLabelFor(direction);
        dl.setDisplayedMnemonic('D');
        direction.setSelectedItem(s.direction());
        form.add(dl);
        form.add(direction);
        JButton run = new JButton("Compute");
        run.setMnemonic('C');
        run.setName("pocket-compute");
        run.addActionListener(e -> compute());
        form.add(run);
        status.setName("pocket-status");
        // a fixed width: "computing" and "done" of another width re-flowed the whole form at every
        // job's start and end, and its fields were painted again on the event thread
        status.setPreferredSize(new java.awt.Dimension(status.getFontMetrics(status.getFont()).stringWidth("m") * 28,
                status.getPreferredSize().height));
        form.add(status);
        report.setEditable(false);
        nc.setEditable(false);
        nc.setName("pocket-nc");
        report.setFont(new java.awt.Font(java.awt.Font.MONOSPACED, java.awt.Font.PLAIN, 12));
        nc.setFont(report.getFont());
        JTabbedPane texts = new JTabbedPane();
        texts.addTab("Recognition tree", new JScrollPane(report));
        texts.addTab("NC program", new JScrollPane(nc));
        JPanel left = new JPanel(new BorderLayout());
        left.add(form, BorderLayout.NORTH);
        left.add(texts, BorderLayout.CENTER);
        panel.add(new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left, plot), BorderLayout.CENTER);
    }

    private void compute() {
        try {
            double[] v = new double[9];
            for (int i = 0; i < 9; i++) {
                v[i] = Double.parseDouble(tech[i].getText().trim());
            }
            model.setSettings(new PocketSettings(Path.of(contour.getText().trim()), v[0], v[1], v[2], v[3], v[4], v[5],
                    v[6], v[7], v[8], (String) post.getSelectedItem(), (String) direction.getSelectedItem()));
        } catch (NumberFormatException ex) {
            status.setText("not a number: " + ex.getMessage());
            status.setToolTipText(status.getText());
            return;
        }
        PocketSettings settings = model.settings();
        status.setText("computing");
        ctx.tasks().start("Pocket", progress -> {
            PocketViewModel.Outcome o = PocketViewModel.outcome(settings);
            return new Shown(o, o.result().map(r -> TextDocuments.of(r.report())).orElse(null),
                    o.result().map(r -> TextDocuments.of(r.nc())).orElse(null));
        }, this::show);
    }

    /** An outcome with its texts as documents, filled off the event thread. */
    private record Shown(PocketViewModel.Outcome outcome, javax.swing.text.Document report,
            javax.swing.text.Document nc) {
    }

    private void show(Shown shown) {
        model.show(shown.outcome());
        Optional<PocketViewModel.Result> r = model.result();
        if (r.isPresent()) {
            report.setDocument(shown.report());
            nc.setDocument(shown.nc());
            nc.setCaretPosition(0);
            plot.show(r.get().scene());
            status.setText("done");
            nc.getHighlighter().removeAllHighlights();
            if (r.get().refusal().isPresent()) {
                org.fresa.check.Failure f = r.get().refusal().get();
                ProgramHighlight.line(nc, f.line());
                status.setText("program refused, not written: " + f.message());
            }
        } else {
            status.setText(model.error().orElse("failed"));
        }
        status.setToolTipText(status.getText());
    }

    @Override
    public String title() {
        return "Pocket";
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
