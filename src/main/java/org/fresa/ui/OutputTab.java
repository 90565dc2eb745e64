package org.fresa.ui;

import java.awt.BorderLayout;
import java.awt.CardLayout;
import java.awt.Color;
import java.awt.Font;
import java.awt.event.KeyEvent;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.ButtonGroup;
import javax.swing.ImageIcon;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JScrollPane;
import javax.swing.JTextPane;
import javax.swing.text.BadLocationException;
import javax.swing.text.SimpleAttributeSet;
import javax.swing.text.StyleConstants;
import javax.swing.text.StyledDocument;
import org.fresa.io.OutputFolder;
import org.fresa.job.JobSettings;
import org.fresa.job.TaskOutcome;

/**
 * The Output tab: the robot formats with check boxes (what Save writes), a preview of one format
 * (program text with its motion keywords coloured, or the joints chart) of the last trajectory
 * the Position tab computed, and Save into folder. Writing runs in the background.
 */
final class OutputTab implements ModuleTab {

    private static final int[] KEYS = {KeyEvent.VK_V, KeyEvent.VK_X, KeyEvent.VK_A, KeyEvent.VK_K, KeyEvent.VK_N};

    static final String NONE = "No programs for this job yet: press Compute in the Position tab, or run the job (F5).";

    private final AppContext ctx;
    private final RobotRunModel runs;
    private final OutputViewModel vm = new OutputViewModel();
    private final JPanel panel = new JPanel(new BorderLayout());
    private final List<JCheckBox> boxes = new ArrayList<>();
    private final JTextPane text = new JTextPane();
    private final JLabel image = new JLabel();
    private final JPanel previewCards = new JPanel(new CardLayout());
    private final JLabel status = new JLabel(NONE);
    // every problem of the last save, not only the first (the status line says how many)
    private final WarningsPanel problems = new WarningsPanel("output-problems", 3);
    // a new result is previewed when the tab is shown, so that computing does not also write a preview
    private boolean stale;

    OutputTab(AppContext ctx, RobotRunModel runs) {
        this.ctx = ctx;
        this.runs = runs;
        JPanel left = new JPanel();
        left.setLayout(new BoxLayout(left, BoxLayout.Y_AXIS));
        left.add(new JLabel("Formats to save"));
        ButtonGroup group = new ButtonGroup();
        JPanel radios = new JPanel();
        radios.setLayout(new BoxLayout(radios, BoxLayout.Y_AXIS));
        int k = 0;
        for (String f : OutputViewModel.FORMATS) {
            JCheckBox b = new JCheckBox(OutputViewModel.describe(f), vm.isChecked(f));
            b.setName("output-format-" + f);
            b.setMnemonic(KEYS[k++]);
            b.addActionListener(e -> {
                vm.setChecked(f, b.isSelected());
                writeFormatsToJob();
            });
            boxes.add(b);
            left.add(b);
            JRadioButton r = new JRadioButton("Preview " + f, f.equals(vm.previewed()));
            r.setName("output-preview-" + f);
            r.addActionListener(e -> {
                vm.preview(f);
                preview();
            });
            group.add(r);
            radios.add(r);
        }
        left.add(javax.swing.Box.createVerticalStrut(10));
        left.add(radios);
        JButton save = new JButton("Save into folder...");
        save.setName("output-save");
        save.setMnemonic(KeyEvent.VK_S);
        save.addActionListener(e -> save());
        left.add(javax.swing.Box.createVerticalStrut(10));
        left.add(save);

        text.setEditable(false);
        text.setName("output-text");
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        image.setName("output-image");
        image.setHorizontalAlignment(JLabel.CENTER);
        previewCards.add(new JScrollPane(text), "text");
        previewCards.add(new JScrollPane(image), "image");
        JPanel right = Captions.above("Preview", KeyEvent.VK_P, text, previewCards);
        status.setName("output-status");

        panel.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
        panel.add(left, BorderLayout.WEST);
        panel.add(right, BorderLayout.CENTER);
        JPanel south = new JPanel(new BorderLayout());
        south.add(status, BorderLayout.NORTH);
        south.add(problems, BorderLayout.CENTER);
        problems.setVisible(false);
        panel.add(south, BorderLayout.SOUTH);
        runs.addListener(this::runsChanged);
        panel.addHierarchyListener(e -> {
            if ((e.getChangeFlags() & java.awt.event.HierarchyEvent.SHOWING_CHANGED) != 0
                    && panel.isShowing()
                    && stale) {
                preview();
            }
        });
        ctx.model().addListener(e -> {
            if (MainViewModel.JOB.equals(e.getPropertyName())) {
                ctx.model().job().robot().ifPresent(rs -> {
                    vm.setCheckedFormats(rs.formats());
                    for (int i = 0; i < boxes.size(); i++) {
                        boxes.get(i).setSelected(vm.isChecked(OutputViewModel.FORMATS.get(i)));
                    }
                });
            }
        });
    }

    @Override
    public String title() {
        return "Output";
    }

    @Override
    public JComponent component() {
        return panel;
    }

    private void writeFormatsToJob() {
        ctx.model()
                .job()
                .robot()
                .ifPresent(rs -> ctx.model()
                        .setJob(ctx.model()
                                .job()
                                .withRobot(new JobSettings.RobotSettings(
                                        rs.robot(),
                                        rs.robotTable(),
                                        rs.tablePiece(),
                                        vm.checkedFormats(),
                                        rs.spindle(),
                                        rs.toolLengthMm(),
                                        rs.placing()))));
    }

    /** New programs (or none): the status says which, the preview follows when the tab is shown. */
    private void runsChanged() {
        showProblems(List.of());
        if (runs.last().isPresent()) {
            RobotRunModel.Run r = runs.last().get();
            status.setText("Trajectory of " + r.programName() + " on "
                    + r.solved().request().robot().name() + ": "
                    + r.solved().result().points().size() + " points");
        } else if (runs.written().isPresent()) {
            RobotRunModel.Written w = runs.written().get();
            status.setText("Programs the run on " + w.robot() + " wrote into " + w.folder());
        } else {
            status.setText(NONE);
        }
        stale = true;
        if (runs.isEmpty()) {
            showNothing();
        } else if (panel.isShowing()) {
            preview();
        }
    }

    private void showNothing() {
        stale = false;
        showText("");
        image.setIcon(null);
        ((CardLayout) previewCards.getLayout()).show(previewCards, "text");
    }

    private void preview() {
        if (runs.isEmpty()) {
            showNothing();
            return;
        }
        RobotRunModel.Run run = runs.last().orElse(null);
        RobotRunModel.Written written = runs.written().orElse(null);
        String format = vm.previewed();
        ctx.tasks()
                .start(
                        "Preview " + format,
                        progress -> {
                            if (written != null) {
                                Path f = written.file(OutputViewModel.fileOf(format))
                                        .orElse(null);
                                if (f == null || !Files.isRegularFile(f)) {
                                    return (Object) new Previewed(
                                            "The run wrote no " + OutputViewModel.fileOf(format)
                                                    + ": tick the format in this tab and run the job again.",
                                            0,
                                            "");
                                }
                                return shown(f, format);
                            }
                            Path scratch = Files.createTempDirectory("fresa-preview");
                            try {
                                Path f = OutputViewModel.previewFile(run, format, scratch);
                                if (format.equals("png")) {
                                    return (Object) ImageIO.read(f.toFile());
                                }
                                String s = Files.readString(f, StandardCharsets.UTF_8);
                                // a preview of a long program shows its beginning; Save writes all of it
                                String shownText = s.length() > 200_000 ? s.substring(0, 200_000) + "\n..." : s;
                                java.util.Optional<org.fresa.check.Failure> refusal =
                                        org.fresa.robot.RobotPrograms.FORMATS.contains(format)
                                                ? OutputViewModel.refusal(run)
                                                : java.util.Optional.empty();
                                return (Object) new Previewed(
                                        shownText,
                                        refusal.map(x -> OutputViewModel.lineOfMotion(shownText, x.line()))
                                                .orElse(0),
                                        refusal.map(org.fresa.check.Failure::message)
                                                .orElse(""));
                            } finally {
                                deleteTree(scratch);
                            }
                        },
                        shown -> {
                            stale = false;
                            CardLayout cards = (CardLayout) previewCards.getLayout();
                            if (shown instanceof java.awt.image.BufferedImage img) {
                                image.setIcon(new ImageIcon(img));
                                cards.show(previewCards, "image");
                            } else {
                                Previewed p = (Previewed) shown;
                                showText(p.text());
                                text.getHighlighter().removeAllHighlights();
                                if (!p.refusal().isEmpty()) {
                                    ProgramHighlight.line(text, p.line());
                                    status.setText("program refused, cannot be saved: " + p.refusal());
                                }
                                cards.show(previewCards, "text");
                            }
                        });
    }

    /** A program preview: its text, and the line of the motion that fails the program check (0: none). */
    private record Previewed(String text, int line, String refusal) {}

    /** The picture or the text of a file to preview. */
    private static Object shown(Path f, String format) throws IOException {
        if (format.equals("png")) {
            return ImageIO.read(f.toFile());
        }
        String s = Files.readString(f, StandardCharsets.UTF_8);
        // a preview of a long program shows its beginning; Save writes all of it
        // a written file passed the program check before it was renamed into place
        return new Previewed(s.length() > 200_000 ? s.substring(0, 200_000) + "\n..." : s, 0, "");
    }

    private void showText(String s) {
        StyledDocument doc = text.getStyledDocument();
        SimpleAttributeSet plain = new SimpleAttributeSet();
        SimpleAttributeSet keyword = new SimpleAttributeSet();
        StyleConstants.setForeground(keyword, new Color(0, 70, 170));
        StyleConstants.setBold(keyword, true);
        try {
            doc.remove(0, doc.getLength());
            doc.insertString(0, s, plain);
            for (int[] span : OutputViewModel.keywordSpans(s)) {
                doc.setCharacterAttributes(span[0], span[1] - span[0], keyword, false);
            }
        } catch (BadLocationException e) {
            throw new IllegalStateException(e);
        }
        text.setCaretPosition(0);
    }

    private void save() {
        String problem = vm.saveProblem(runs.last().isPresent());
        if (runs.last().isEmpty() && runs.written().isPresent()) {
            problem = "The run wrote its programs into " + runs.written().get().folder()
                    + " already: press Compute in the Position tab to save them elsewhere.";
        }
        if (!problem.isEmpty()) {
            Dialogs.error(ctx.owner(), "Save", problem);
            return;
        }
        if (vm.checkedFormats().stream().anyMatch(org.fresa.robot.RobotPrograms.FORMATS::contains)) {
            java.util.Optional<org.fresa.check.Failure> refusal = runs.last().isPresent()
                    ? OutputViewModel.refusal(runs.last().get())
                    : java.util.Optional.empty();
            if (refusal.isPresent()) {
                Dialogs.error(
                        ctx.owner(),
                        "Save",
                        "The robot program fails the program check and cannot be saved: "
                                + refusal.get().message());
                return;
            }
        }
        JFileChooser fc = FileChoosers.chooser(FileChoosers.Kind.FOLDER);
        fc.setDialogTitle("Save robot programs into folder");
        if (fc.showSaveDialog(ctx.owner()) != JFileChooser.APPROVE_OPTION) {
            return;
        }
        saveInto(FileChoosers.chosen(fc));
    }

    void saveInto(Path dir) {
        RobotRunModel.Run run = runs.last().orElseThrow();
        List<String> formats = vm.checkedFormats();
        ctx.tasks()
                .start(
                        "Saving robot programs",
                        progress -> OutputViewModel.write(run, formats, new OutputFolder(dir)),
                        (TaskOutcome o) -> {
                            status.setText("Saved " + o.files().size() + " files into " + dir
                                    + (o.problems().isEmpty()
                                            ? ""
                                            : "; " + o.problems().size()
                                                    + (o.problems().size() == 1 ? " problem" : " problems")
                                                    + ", listed below"));
                            showProblems(o.problems());
                        });
    }

    /** Lists every problem, or hides the list when there is none. */
    private void showProblems(List<String> all) {
        problems.show(WarningList.of(all));
        problems.setVisible(!all.isEmpty());
        panel.revalidate();
    }

    private static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }
}
