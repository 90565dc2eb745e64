package org.fresa.job;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBElement;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.Marshaller;
import jakarta.xml.bind.UnmarshalException;
import jakarta.xml.bind.Unmarshaller;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.validation.Schema;
import org.fresa.cell.TablePlacing;
import org.fresa.geom.Vec2;
import org.fresa.io.AtomicFiles;
import org.fresa.io.SafeXml;
import org.fresa.io.XmlLines;
import org.fresa.job.JobSettings.CuttingSettings;
import org.fresa.job.JobSettings.GradingSettings;
import org.fresa.job.JobSettings.OutputSettings;
import org.fresa.job.JobSettings.PocketSettings;
import org.fresa.job.JobSettings.RobotSettings;
import org.fresa.job.JobSettings.SoleSettings;
import org.fresa.job.JobSettings.StepNcSettings;
import org.fresa.job.xml.CuttingType;
import org.fresa.job.xml.GradingType;
import org.fresa.job.xml.JobType;
import org.fresa.job.xml.ObjectFactory;
import org.fresa.job.xml.OutputsType;
import org.fresa.job.xml.PlacementType;
import org.fresa.job.xml.PocketType;
import org.fresa.job.xml.RobotType;
import org.fresa.job.xml.SoleType;
import org.fresa.job.xml.StepNcType;
import org.fresa.model.CamInputException;
import org.fresa.model.FileChecks;
import org.fresa.model.Placement;
import org.fresa.setting.SettingChoice;
import org.fresa.setting.SettingRange;
import org.fresa.setting.SettingRanges;
import org.fresa.setting.SettingRanges.Cutting;
import org.fresa.setting.SettingRanges.Grading;
import org.fresa.setting.SettingRanges.Pocket;
import org.fresa.setting.SettingRanges.Sole;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/**
 * Reads and writes job files ({@code schemas/job.xsd}) with Jakarta XML Binding.
 *
 * <p>Reading validates against the schema and refuses any DOCTYPE, so external entities (XXE)
 * and entity expansion cannot happen. Paths in the file are relative to the file's folder.
 */
public final class JobXml {

    /** The current job file version. */
    public static final int VERSION = 1;

    private static final Schema SCHEMA = SafeXml.schema("/schemas/job.xsd");
    private static final JAXBContext CONTEXT = createContext();

    private JobXml() {}

    private static JAXBContext createContext() {
        try {
            return JAXBContext.newInstance(ObjectFactory.class);
        } catch (JAXBException e) {
            throw new IllegalStateException("cannot set up job XML binding", e);
        }
    }

    /**
     * Reads and validates a job file.
     *
     * @throws CamInputException when the file cannot be read, is not well-formed, has a DOCTYPE or
     *     does not match the schema (with line and column)
     */
    public static Job read(Path file) throws CamInputException {
        String name = file.toString();
        FileChecks.requireInput(file, "a job file", FileChecks.MAX_TEXT_FILE_BYTES);
        JobType xml;
        try (InputStream in = Files.newInputStream(file)) {
            Unmarshaller u = CONTEXT.createUnmarshaller();
            u.setSchema(SCHEMA);
            JAXBElement<JobType> root = u.unmarshal(SafeXml.source(in, file), JobType.class);
            xml = root.getValue();
        } catch (IOException e) {
            throw new CamInputException(name, "cannot read the job file (" + e.getMessage() + ")");
        } catch (UnmarshalException e) {
            throw fromUnmarshal(name, e);
        } catch (JAXBException | SAXException | ParserConfigurationException e) {
            throw new CamInputException(name, "not a valid job file: " + e.getMessage());
        }
        if (xml.getVersion() > VERSION) {
            throw new CamInputException(
                    name,
                    "job file version " + xml.getVersion() + " is newer than this Fresa understands (" + VERSION + ")");
        }
        Path base = file.toAbsolutePath().getParent();
        try {
            return fromXml(xml, base);
        } catch (SettingRange.OutOfRange e) {
            throw new CamInputException(
                    name,
                    XmlLines.lineOf(file, e.range().attribute(), e.value()),
                    0,
                    e.range().attribute() + ": " + e.range().problem(e.value()));
        } catch (SettingChoice.Unknown e) {
            throw new CamInputException(
                    name, XmlLines.lineOf(file, e.choice().attribute(), e.text()), 0, e.getMessage());
        } catch (BadEntry e) {
            int line = e.attribute == null ? 0 : XmlLines.lineOf(file, e.attribute, e.word);
            throw line > 0
                    ? new CamInputException(name, line, 0, e.getMessage())
                    : new CamInputException(name, e.getMessage());
        }
    }

    private static CamInputException fromUnmarshal(String name, UnmarshalException e) {
        Throwable c = e.getLinkedException() != null ? e.getLinkedException() : e.getCause();
        if (c instanceof SAXParseException spe) {
            String msg = spe.getMessage();
            if (msg != null && msg.contains("DOCTYPE")) {
                msg = "a DOCTYPE is not allowed in a job file (external entities are refused)";
            } else {
                msg = "expected a job as schemas/job.xsd describes: " + msg;
            }
            return new CamInputException(
                    name, Math.max(0, spe.getLineNumber()), Math.max(0, spe.getColumnNumber()), msg, e);
        }
        return new CamInputException(
                name, 0, 0, "not a valid job file: " + (c != null ? c.getMessage() : e.getMessage()), e);
    }

    /** Writes a job; file paths are stored relative to the job file's folder where possible. */
    public static void write(Job job, Path file) throws IOException {
        Path base = file.toAbsolutePath().getParent();
        JobType xml = toXml(job, base);
        AtomicFiles.write(file, out -> marshal(xml, out));
    }

    private static void marshal(JobType xml, OutputStream out) throws IOException {
        try {
            Marshaller m = CONTEXT.createMarshaller();
            m.setProperty(Marshaller.JAXB_FORMATTED_OUTPUT, Boolean.TRUE);
            m.setProperty(Marshaller.JAXB_ENCODING, "UTF-8");
            m.setSchema(SCHEMA);
            m.marshal(new ObjectFactory().createJob(xml), out);
        } catch (JAXBException e) {
            throw new IOException("cannot write the job: " + e.getMessage(), e);
        }
    }

    /** A STEP-NC entry the job file asks for that no tool may make (a plunge of a cutter not said to cut at its centre). */
    private static final class BadEntry extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        /** The attribute and its word that find the entry's line, or null. */
        final String attribute;

        final String word;

        BadEntry(String message) {
            this(message, null, null);
        }

        BadEntry(String message, String attribute, String word) {
            super(message);
            this.attribute = attribute;
            this.word = word;
        }
    }

    /** The planner's own cut order of a job's {@code <cutting>}, every point checked against the machine's travel. */
    private static org.fresa.cutting.CutOrderOverride cutOrder(org.fresa.job.xml.CutOrderType t) {
        if (t == null) {
            return org.fresa.cutting.CutOrderOverride.NONE;
        }
        List<org.fresa.cutting.CutOrderOverride.Cut> cuts = new java.util.ArrayList<>();
        for (org.fresa.job.xml.OrderedCutType c : t.getCut()) {
            Vec2 at = Vec2.of(Cutting.CUT_X.require(c.getXMm()), Cutting.CUT_Y.require(c.getYMm()));
            if ((c.getStartXMm() == null) != (c.getStartYMm() == null)) {
                throw new BadEntry(
                        "<cut contour=\"" + c.getContour() + "\"> has one of startXMm and startYMm: give"
                                + " both (the start point) or neither (the automatic start)",
                        "contour",
                        c.getContour());
            }
            Optional<Vec2> start = c.getStartXMm() == null
                    ? Optional.empty()
                    : Optional.of(Vec2.of(
                            Cutting.START_X.require(c.getStartXMm()), Cutting.START_Y.require(c.getStartYMm())));
            cuts.add(new org.fresa.cutting.CutOrderOverride.Cut(c.getContour(), at, start));
        }
        return new org.fresa.cutting.CutOrderOverride(cuts);
    }

    /** The entry of a job's {@code <stepnc>}, its angle checked against the option's range. */
    private static org.fresa.pocket.EntryRule stepNcEntry(StepNcType s) {
        org.fresa.pocket.EntryRule.Kind kind = org.fresa.pocket.EntryRule.Kind.of(s.getEntry())
                .orElseThrow(() -> new BadEntry("<stepnc> entry=\"" + s.getEntry() + "\": expected one of "
                        + String.join(", ", org.fresa.pocket.EntryRule.Kind.words())));
        double angle = SettingRanges.StepNc.ENTRY_ANGLE.require(s.getEntryAngleDeg());
        if (kind == org.fresa.pocket.EntryRule.Kind.PLUNGE && !s.isCentreCutting()) {
            throw new BadEntry("<stepnc> entry=\"plunge\" needs centreCutting=\"true\": a cutter not said to cut at"
                    + " its centre never goes straight down into material");
        }
        return new org.fresa.pocket.EntryRule(kind, angle, s.isCentreCutting());
    }

    /** The name a typed contour goes by when the job names no file for it. */
    static final String TYPED_CONTOUR = "contour.dad";

    /** The contour held in the job; the schema bounds every number (|value| <= 1e6 mm, radius >= 0). */
    private static org.fresa.pocket.DadContour pocketElements(org.fresa.job.xml.PocketElementsType x) {
        List<org.fresa.pocket.DadElement> out = new java.util.ArrayList<>();
        for (Object o : x.getLineOrArc()) {
            if (o instanceof org.fresa.job.xml.PocketLineType l) {
                if (l.getA() == 0 && l.getB() == 0) {
                    throw new BadEntry(
                            "<line> element " + (out.size() + 1) + ": a and b are both zero, which is no line",
                            "a",
                            "0");
                }
                out.add(new org.fresa.pocket.DadElement(
                        false, l.getA(), l.getB(), l.getDMm(), selector(l.getSelector()), ' '));
            } else {
                org.fresa.job.xml.PocketArcType a = (org.fresa.job.xml.PocketArcType) o;
                out.add(new org.fresa.pocket.DadElement(
                        true,
                        a.getXMm(),
                        a.getYMm(),
                        a.getRadiusMm(),
                        selector(a.getSelector()),
                        "concave".equals(a.getSense()) ? 'M' : 'F'));
            }
        }
        return new org.fresa.pocket.DadContour(out);
    }

    private static char selector(org.fresa.job.xml.DadSelector s) {
        return s == null ? ' ' : s.value().charAt(0);
    }

    private static org.fresa.job.xml.PocketElementsType pocketElements(org.fresa.pocket.DadContour c) {
        org.fresa.job.xml.PocketElementsType x = new org.fresa.job.xml.PocketElementsType();
        for (org.fresa.pocket.DadElement e : c.elements()) {
            org.fresa.job.xml.DadSelector sel =
                    e.selector() == ' ' ? null : org.fresa.job.xml.DadSelector.fromValue(String.valueOf(e.selector()));
            if (e.arc()) {
                org.fresa.job.xml.PocketArcType a = new org.fresa.job.xml.PocketArcType();
                a.setXMm(e.a());
                a.setYMm(e.b());
                a.setRadiusMm(e.d());
                a.setSelector(sel);
                a.setSense(e.sense() == 'M' ? "concave" : "convex");
                x.getLineOrArc().add(a);
            } else {
                org.fresa.job.xml.PocketLineType l = new org.fresa.job.xml.PocketLineType();
                l.setA(e.a());
                l.setB(e.b());
                l.setDMm(e.d());
                l.setSelector(sel);
                x.getLineOrArc().add(l);
            }
        }
        return x;
    }

    private static Path resolve(Path base, String ref) {
        return base.resolve(ref).normalize();
    }

    private static String relativize(Path base, Path p) {
        Path abs = p.toAbsolutePath().normalize();
        try {
            return base.relativize(abs).toString().replace('\\', '/');
        } catch (IllegalArgumentException e) {
            return abs.toString();
        }
    }

    private static List<String> splitList(String s) {
        return Arrays.stream(s.split(","))
                .map(String::trim)
                .filter(t -> !t.isEmpty())
                .toList();
    }

    /** The robot's formats as written, each one checked (a typo is refused when the job is read). */
    private static List<String> robotFormats(String text) {
        return splitList(text).stream()
                .map(f -> SettingRanges.Robot.FORMAT.require(f).word())
                .toList();
    }

    static Job fromXml(JobType x, Path base) {
        Job job = Job.empty(JobTask.ofId(x.getTask().value()));
        if (!x.getRuns().isEmpty()) {
            java.util.List<JobTask> runs = new java.util.ArrayList<>();
            runs.add(job.task());
            x.getRuns().forEach(t -> runs.add(JobTask.ofId(t.value())));
            job = job.withRuns(runs);
        }
        if (x.getName() != null) {
            job = job.withName(x.getName());
        }
        StepNcType s = x.getStepnc();
        if (s != null) {
            job = job.withStepnc(new StepNcSettings(
                    resolve(base, s.getFile()),
                    SettingRanges.StepNc.POST.require(s.getPost()),
                    s.isTrustCuttingSpeed(),
                    SettingRanges.StepNc.BREAKTHROUGH.require(s.getBreakthroughMm()),
                    stepNcEntry(s),
                    org.fresa.toolpath.PathConvention.byWord(s.getPaths())
                            .orElseThrow(() ->
                                    new IllegalArgumentException("paths must be fresa or thesis: " + s.getPaths()))));
        }
        RobotType r = x.getRobot();
        if (r != null) {
            job = job.withRobot(new RobotSettings(
                    r.getRobot(),
                    placement(r.getRobotTable()),
                    placement(r.getTablePiece()),
                    robotFormats(r.getFormats()),
                    r.getSpindle() == null
                            ? java.util.Optional.empty()
                            : java.util.Optional.of(SettingRanges.Robot.requireSpindle(placement(r.getSpindle()))),
                    r.getToolLengthMm() == null
                            ? OptionalDouble.empty()
                            : OptionalDouble.of(SettingRanges.Robot.TOOL_LENGTH.require(r.getToolLengthMm())),
                    "auto".equals(r.getPlace()) ? TablePlacing.AUTO : TablePlacing.GIVEN));
        }
        PocketType p = x.getPocket();
        if (p != null) {
            if (p.getContour() == null && p.getElements() == null) {
                throw new BadEntry("<pocket> needs a contour file (contour=\"...\") or its <elements>");
            }
            Optional<org.fresa.pocket.DadContour> elements =
                    p.getElements() == null ? Optional.empty() : Optional.of(pocketElements(p.getElements()));
            job = job.withPocket(new PocketSettings(
                    resolve(base, p.getContour() == null ? TYPED_CONTOUR : p.getContour()),
                    Pocket.TOOL_DIAMETER.require(p.getToolDiameterMm()),
                    Pocket.CUT.require(p.getCutFraction()),
                    Pocket.FINISH.require(p.getFinishFraction()),
                    Pocket.Z_TOP.require(p.getZTopMm()),
                    Pocket.Z_BOTTOM.require(p.getZBottomMm()),
                    Pocket.MAX_DEPTH.require(p.getMaxDepthPerPassMm()),
                    Pocket.SPINDLE.require(p.getSpindleRpm()),
                    Pocket.FEED.require(p.getFeedMmPerMin()),
                    Pocket.FINISH_FEED.require(p.getFinishFeedMmPerMin()),
                    Pocket.POST.require(p.getPost()),
                    Pocket.DIRECTION.require(p.getDirection()),
                    Pocket.ENTRY.require(p.getEntry()),
                    Pocket.ENTRY_ANGLE.require(p.getEntryAngleDeg()),
                    p.isCentreCutting(),
                    elements,
                    new org.fresa.pocket.PocketStrategy(
                            Pocket.STRATEGY.require(p.getStrategy()),
                            Pocket.ANGLE.require(p.getAngleDeg()),
                            Pocket.STOCK_TO_LEAVE.require(p.getStockToLeaveMm()),
                            Pocket.ORDER.require(p.getOrder()),
                            p.getRestToolDiameterMm() == null
                                    ? 0
                                    : PocketService.restToolRange(p.getToolDiameterMm())
                                            .require(p.getRestToolDiameterMm()))));
        }
        CuttingType c = x.getCutting();
        if (c != null) {
            job = job.withCutting(new CuttingSettings(
                    resolve(base, c.getDrawing()),
                    Cutting.KERF.require(c.getKerfMm()),
                    Cutting.PROCESS.require(c.getProcess()),
                    Cutting.LEAD_IN.require(c.getLeadInMm()),
                    Cutting.LEAD_OUT.require(c.getLeadOutMm()),
                    Cutting.LEAD.require(c.getLead()),
                    Cutting.TOLERANCE.require(c.getToleranceMm()),
                    Cutting.UNITS.require(c.getUnits()),
                    c.isPaperMode(),
                    Cutting.POST.require(c.getPost()),
                    Cutting.COMPENSATION.require(c.getCompensation()),
                    Cutting.OUTER_DIRECTION.require(c.getOuterDirection()),
                    Cutting.HOLE_DIRECTION.require(c.getHoleDirection()),
                    Cutting.OVERCUT.require(c.getOvercutMm()),
                    c.isAvoidCutParts(),
                    cutOrder(c.getCutOrder())));
        }
        GradingType g = x.getGrading();
        if (g != null) {
            Optional<Vec2> origin = g.getOriginXMm() != null && g.getOriginYMm() != null
                    ? Optional.of(Vec2.of(
                            Grading.ORIGIN_X.require(g.getOriginXMm()), Grading.ORIGIN_Y.require(g.getOriginYMm())))
                    : Optional.empty();
            job = job.withGrading(new GradingSettings(
                    resolve(base, g.getOutline()),
                    Grading.BASE_SIZE.require(g.getBaseSize()),
                    g.getSizes(),
                    g.isHalfSizes(),
                    Grading.SYSTEM.require(g.getSystem()),
                    optional(Grading.LENGTH_STEP, g.getLengthStepMm()),
                    optional(Grading.WIDTH_STEP, g.getWidthStepMm()),
                    origin,
                    Grading.SHRINKAGE.require(g.getShrinkage()),
                    Grading.SHRINKAGE_MODE.require(g.getShrinkageMode()),
                    heel(g)));
        }
        SoleType so = x.getSole();
        if (so != null) {
            job = job.withSole(soleSettings(so, base));
        }
        OutputsType o = x.getOutputs();
        if (o != null) {
            job = job.withOutputs(new OutputSettings(splitList(o.getFormats())));
        }
        return job;
    }

    /** The grading's heel coordination: by the designated elements, or a boundary, or none. */
    private static Optional<JobSettings.HeelCoordination> heel(GradingType g) {
        boolean elements = g.getHeelElements() != null && !g.getHeelElements().isBlank();
        if (!elements && g.getCoordinationMm() == null) {
            return Optional.empty();
        }
        int group = Grading.HEEL_GROUP.require(g.getHeelGroup());
        // both given is refused when the plan is made, with the job's other grading settings
        return Optional.of(new JobSettings.HeelCoordination(
                group,
                g.getCoordinationMm() == null
                        ? OptionalDouble.empty()
                        : OptionalDouble.of(Grading.COORDINATION.require(g.getCoordinationMm())),
                elements ? g.getHeelElements().trim() : ""));
    }

    private static SoleSettings soleSettings(SoleType so, Path base) {
        Optional<Vec2> origin = so.getOriginXMm() != null && so.getOriginYMm() != null
                ? Optional.of(
                        Vec2.of(Sole.ORIGIN_X.require(so.getOriginXMm()), Sole.ORIGIN_Y.require(so.getOriginYMm())))
                : Optional.empty();
        List<JobSettings.SoleTool> tools = so.getTool().stream()
                .map(t -> new JobSettings.SoleTool(
                        t.getId(),
                        Sole.TOOL_NUMBER.require(t.getNumber()),
                        Sole.TOOL_DIAMETER.require(t.getDiameterMm()),
                        Sole.TOOL_SPINDLE.require(t.getSpindleRpm()),
                        Sole.TOOL_FEED.require(t.getFeedMmPerMin()),
                        Sole.TOOL_PLUNGE_FEED.require(t.getPlungeFeedMmPerMin())))
                .toList();
        List<JobSettings.SoleDesign> designs = so.getDesign().stream()
                .map(d -> new JobSettings.SoleDesign(
                        d.getName(),
                        d.getTool(),
                        Sole.RULE.require(d.getRule()),
                        d.isText(),
                        Sole.PATTERN.require(d.getPattern()),
                        Sole.COUNT.require(d.getCount()),
                        Sole.ROWS.require(d.getRows()),
                        Sole.DX.require(d.getDxMm()),
                        Sole.DY.require(d.getDyMm()),
                        Sole.ROW_SHIFT.require(d.getRowShiftMm()),
                        Sole.STEP.require(d.getStepDeg()),
                        Sole.CENTER_X.require(d.getCenterXMm()),
                        Sole.CENTER_Y.require(d.getCenterYMm()),
                        d.getLead().stream()
                                .map(f -> new JobSettings.SoleFigure(f.getMacro(), f.getParams()))
                                .toList(),
                        d.getFigure().stream()
                                .map(f -> new JobSettings.SoleFigure(
                                        f.getMacro(),
                                        f.getParams(),
                                        f.getFile() == null || f.getFile().isBlank()
                                                ? Optional.<Path>empty()
                                                : Optional.of(resolve(base, f.getFile()))))
                                .toList(),
                        d.getCopy().stream()
                                .map(c -> new JobSettings.SoleCopy(
                                        Sole.DX.require(c.getDxMm()),
                                        Sole.DY.require(c.getDyMm()),
                                        optional(Sole.MIRROR_X, c.getMirrorXMm()),
                                        optional(Sole.MIRROR_Y, c.getMirrorYMm()),
                                        Sole.ROTATE.require(c.getRotateDeg())))
                                .toList()))
                .toList();
        return new SoleSettings(
                resolve(base, so.getOutline()),
                Sole.BASE_SIZE.require(so.getBaseSize()),
                so.getSizes(),
                Sole.CAVITY_DEPTH.require(so.getCavityDepthMm()),
                Sole.POST.require(so.getPost()),
                Sole.SYSTEM.require(so.getSystem()),
                origin,
                Sole.SHRINKAGE.require(so.getShrinkage()),
                Sole.SHRINKAGE_MODE.require(so.getShrinkageMode()),
                Sole.TREAD_DEPTH.require(so.getTreadDepthMm()),
                Sole.CLEARANCE.require(so.getClearanceMm()),
                Sole.MARGIN.require(so.getMarginMm()),
                tools,
                designs,
                so.getCavityTool(),
                block(so.getBlock()));
    }

    private static Optional<JobSettings.SoleBlock> block(SoleType.Block b) {
        if (b == null) {
            return Optional.empty();
        }
        return Optional.of(new JobSettings.SoleBlock(
                Sole.BLOCK_D.require(b.getDMm()),
                Sole.BLOCK_DLM.require(b.getDlmMm()),
                Sole.BLOCK_E.require(b.getEMm()),
                Sole.BLOCK_S.require(b.getSMm()),
                Sole.BLOCK_CM.require(b.getCmMm()),
                optional(Sole.BLOCK_CP, b.getCpMm()),
                optional(Sole.BLOCK_DPI, b.getDpiMm()),
                optional(Sole.BLOCK_XTANP, b.getXtanpMm())));
    }

    private static SoleType soleType(SoleSettings s, Path base) {
        SoleType t = new SoleType();
        t.setOutline(relativize(base, s.outline()));
        t.setBaseSize(s.baseSize());
        t.setSizes(s.sizes());
        t.setCavityDepthMm(s.cavityDepthMm());
        t.setPost(s.post().word());
        t.setSystem(s.system().id());
        s.originMm().ifPresent(o -> {
            t.setOriginXMm(o.x());
            t.setOriginYMm(o.y());
        });
        t.setShrinkage(s.shrinkage());
        t.setShrinkageMode(s.shrinkageMode().id());
        t.setTreadDepthMm(s.treadDepthMm());
        t.setClearanceMm(s.clearanceMm());
        t.setMarginMm(s.marginMm());
        t.setCavityTool(s.cavityTool());
        s.block().ifPresent(b -> {
            SoleType.Block x = new SoleType.Block();
            x.setDMm(b.dMm());
            x.setDlmMm(b.dlmMm());
            x.setEMm(b.eMm());
            x.setSMm(b.sMm());
            x.setCmMm(b.cmMm());
            b.cpMm().ifPresent(x::setCpMm);
            b.dpiMm().ifPresent(x::setDpiMm);
            b.xtanpMm().ifPresent(x::setXtanpMm);
            t.setBlock(x);
        });
        for (JobSettings.SoleTool k : s.tools()) {
            SoleType.Tool x = new SoleType.Tool();
            x.setId(k.id());
            x.setNumber(k.number());
            x.setDiameterMm(k.diameterMm());
            x.setSpindleRpm(k.spindleRpm());
            x.setFeedMmPerMin(k.feedMmPerMin());
            x.setPlungeFeedMmPerMin(k.plungeFeedMmPerMin());
            t.getTool().add(x);
        }
        for (JobSettings.SoleDesign d : s.designs()) {
            SoleType.Design x = new SoleType.Design();
            x.setName(d.name());
            x.setTool(d.tool());
            x.setRule(d.rule().id());
            x.setText(d.text());
            x.setPattern(d.pattern().word());
            x.setCount(d.count());
            x.setRows(d.rows());
            x.setDxMm(d.dxMm());
            x.setDyMm(d.dyMm());
            x.setRowShiftMm(d.rowShiftMm());
            x.setStepDeg(d.stepDeg());
            x.setCenterXMm(d.centerXMm());
            x.setCenterYMm(d.centerYMm());
            d.lead().forEach(f -> x.getLead().add(figure(f)));
            d.figures().forEach(f -> {
                org.fresa.job.xml.SoleFigureType y = figure(f);
                f.drawing().ifPresent(file -> y.setFile(relativize(base, file)));
                x.getFigure().add(y);
            });
            for (JobSettings.SoleCopy c : d.copies()) {
                SoleType.Design.Copy y = new SoleType.Design.Copy();
                y.setDxMm(c.dxMm());
                y.setDyMm(c.dyMm());
                c.mirrorXMm().ifPresent(y::setMirrorXMm);
                c.mirrorYMm().ifPresent(y::setMirrorYMm);
                y.setRotateDeg(c.rotateDeg());
                x.getCopy().add(y);
            }
            t.getDesign().add(x);
        }
        return t;
    }

    private static org.fresa.job.xml.SoleFigureType figure(JobSettings.SoleFigure f) {
        org.fresa.job.xml.SoleFigureType t = new org.fresa.job.xml.SoleFigureType();
        t.setMacro(f.macro());
        t.setParams(f.params());
        return t;
    }

    private static OptionalDouble optional(SettingRange range, Double d) {
        return d == null ? OptionalDouble.empty() : OptionalDouble.of(range.require(d));
    }

    private static Placement placement(PlacementType p) {
        if (p == null) {
            return Placement.ORIGIN;
        }
        return SettingRanges.Robot.require(
                new Placement(p.getXMm(), p.getYMm(), p.getZMm(), p.getRxDeg(), p.getRyDeg(), p.getRzDeg()));
    }

    private static PlacementType placement(Placement p) {
        PlacementType t = new PlacementType();
        t.setXMm(p.xMm());
        t.setYMm(p.yMm());
        t.setZMm(p.zMm());
        t.setRxDeg(p.rxDeg());
        t.setRyDeg(p.ryDeg());
        t.setRzDeg(p.rzDeg());
        return t;
    }

    static JobType toXml(Job job, Path base) {
        JobType x = new JobType();
        x.setVersion(VERSION);
        x.setTask(org.fresa.job.xml.TaskType.fromValue(job.task().id()));
        if (job.runs().size() > 1) {
            job.runs().forEach(t -> x.getRuns().add(org.fresa.job.xml.TaskType.fromValue(t.id())));
        }
        x.setName(job.name());
        job.stepnc().ifPresent(s -> {
            StepNcType t = new StepNcType();
            t.setFile(relativize(base, s.file()));
            t.setPost(s.post().word());
            // written only when not the default, so that saved jobs stay as they were
            if (s.trustCuttingSpeed()) {
                t.setTrustCuttingSpeed(true);
            }
            if (s.breakthroughMm() != org.fresa.toolpath.PlanningChoices.DEFAULT_BREAKTHROUGH_MM) {
                t.setBreakthroughMm(s.breakthroughMm());
            }
            if (!s.entry().equals(org.fresa.pocket.EntryRule.DEFAULT)) {
                t.setEntry(s.entry().kind().word());
                t.setEntryAngleDeg(s.entry().angleDeg());
                t.setCentreCutting(s.entry().centreCutting());
            }
            if (s.paths() != org.fresa.toolpath.PathConvention.FRESA) {
                t.setPaths(s.paths().word());
            }
            x.setStepnc(t);
        });
        job.robot().ifPresent(r -> {
            RobotType t = new RobotType();
            t.setRobot(r.robot());
            t.setRobotTable(placement(r.robotTable()));
            t.setTablePiece(placement(r.tablePiece()));
            t.setFormats(String.join(",", r.formats()));
            r.spindle().ifPresent(sp -> t.setSpindle(placement(sp)));
            if (r.toolLengthMm().isPresent()) {
                t.setToolLengthMm(r.toolLengthMm().getAsDouble());
            }
            if (r.placing() != TablePlacing.GIVEN) {
                t.setPlace(r.placing().id());
            }
            x.setRobot(t);
        });
        job.pocket().ifPresent(p -> {
            PocketType t = new PocketType();
            t.setContour(relativize(base, p.contour()));
            t.setToolDiameterMm(p.toolDiameterMm());
            t.setCutFraction(p.cutFraction());
            t.setFinishFraction(p.finishFraction());
            t.setZTopMm(p.zTopMm());
            t.setZBottomMm(p.zBottomMm());
            t.setMaxDepthPerPassMm(p.maxDepthPerPassMm());
            t.setSpindleRpm(p.spindleRpm());
            t.setFeedMmPerMin(p.feedMmPerMin());
            t.setFinishFeedMmPerMin(p.finishFeedMmPerMin());
            t.setPost(p.post().word());
            t.setDirection(p.direction().word());
            t.setEntry(p.entry().word());
            t.setEntryAngleDeg(p.entryAngleDeg());
            t.setCentreCutting(p.centreCutting());
            // written only when not the default: a job saved with the defaults reads as it always has
            org.fresa.pocket.PocketStrategy st = p.strategy();
            if (st.kind() != org.fresa.pocket.PocketStrategy.DEFAULT.kind()) {
                t.setStrategy(st.kind().word());
            }
            if (st.angleDeg() != org.fresa.pocket.PocketStrategy.DEFAULT.angleDeg()) {
                t.setAngleDeg(st.angleDeg());
            }
            if (st.stockToLeaveMm() != org.fresa.pocket.PocketStrategy.DEFAULT.stockToLeaveMm()) {
                t.setStockToLeaveMm(st.stockToLeaveMm());
            }
            if (st.restTool()) {
                t.setRestToolDiameterMm(st.restToolDiameterMm());
            }
            if (st.order() != org.fresa.pocket.PocketStrategy.DEFAULT.order()) {
                t.setOrder(st.order().word());
            }
            p.elements().ifPresent(c -> t.setElements(pocketElements(c)));
            x.setPocket(t);
        });
        job.cutting().ifPresent(c -> {
            CuttingType t = new CuttingType();
            t.setDrawing(relativize(base, c.drawing()));
            t.setKerfMm(c.kerfMm());
            t.setProcess(c.process().id());
            t.setLeadInMm(c.leadInMm());
            t.setLeadOutMm(c.leadOutMm());
            t.setLead(c.lead().word());
            t.setToleranceMm(c.toleranceMm());
            t.setUnits(c.units().word());
            t.setPaperMode(c.paperMode());
            t.setPost(c.post().id());
            t.setCompensation(c.compensation().word());
            t.setOuterDirection(c.outerDirection().word());
            t.setHoleDirection(c.holeDirection().word());
            t.setOvercutMm(c.overcutMm());
            t.setAvoidCutParts(c.avoidCutParts());
            if (!c.cutOrder().isEmpty()) {
                org.fresa.job.xml.CutOrderType order = new org.fresa.job.xml.CutOrderType();
                for (org.fresa.cutting.CutOrderOverride.Cut k : c.cutOrder().cuts()) {
                    org.fresa.job.xml.OrderedCutType e = new org.fresa.job.xml.OrderedCutType();
                    e.setContour(k.contour());
                    e.setXMm(k.atMm().x());
                    e.setYMm(k.atMm().y());
                    k.startMm().ifPresent(p -> {
                        e.setStartXMm(p.x());
                        e.setStartYMm(p.y());
                    });
                    order.getCut().add(e);
                }
                t.setCutOrder(order);
            }
            x.setCutting(t);
        });
        job.grading().ifPresent(g -> {
            GradingType t = new GradingType();
            t.setOutline(relativize(base, g.outline()));
            t.setBaseSize(g.baseSize());
            t.setSizes(g.sizes());
            t.setHalfSizes(g.halfSizes());
            t.setSystem(g.system().id());
            g.lengthStepMm().ifPresent(t::setLengthStepMm);
            g.widthStepMm().ifPresent(t::setWidthStepMm);
            g.originMm().ifPresent(o -> {
                t.setOriginXMm(o.x());
                t.setOriginYMm(o.y());
            });
            t.setShrinkage(g.shrinkage());
            t.setShrinkageMode(g.shrinkageMode().id());
            g.coordination().ifPresent(h -> {
                t.setHeelGroup(h.groupSize());
                h.boundaryMm().ifPresent(t::setCoordinationMm);
                if (!h.heelElements().isBlank()) {
                    t.setHeelElements(h.heelElements());
                }
            });
            x.setGrading(t);
        });
        job.sole().ifPresent(s -> x.setSole(soleType(s, base)));
        OutputsType o = new OutputsType();
        o.setFormats(String.join(",", job.outputs().formats()));
        x.setOutputs(o);
        return x;
    }
}
