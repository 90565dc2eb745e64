package org.fresa.robot;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBElement;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.Marshaller;
import jakarta.xml.bind.UnmarshalException;
import jakarta.xml.bind.Unmarshaller;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.math.BigInteger;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.validation.Schema;
import org.fresa.geom.Quaternion;
import org.fresa.geom.Transform3;
import org.fresa.geom.Vec3;
import org.fresa.io.SafeXml;
import org.fresa.model.CamInputException;
import org.fresa.post.RapidWriter;
import org.fresa.post.RobotProgram;
import org.fresa.robot.program.ActivityListType;
import org.fresa.robot.program.ActivityType;
import org.fresa.robot.program.CartesianTargetType;
import org.fresa.robot.program.JointDefinitionType;
import org.fresa.robot.program.JointTargetType;
import org.fresa.robot.program.JointTypeType;
import org.fresa.robot.program.JointUnitsType;
import org.fresa.robot.program.JointValueType;
import org.fresa.robot.program.MoveAttributesType;
import org.fresa.robot.program.ObjectFactory;
import org.fresa.robot.program.ResourceType;
import org.fresa.robot.program.RobotProgramType;
import org.fresa.robot.program.ToolFrameType;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/**
 * The offline-programming XML of a robot program ({@code program.xml},
 * {@code schemas/robot-program.xsd}), written and read with Jakarta XML Binding. Reading validates
 * against the schema; writing checks what the binding cannot guarantee (see {@link #write}).
 * Joint values and positions are written as exact doubles, so reading a file back gives the same
 * joints bit for bit.
 */
public final class RobotProgramXml {

    public static final int VERSION = 1;
    /** Only reading needs the compiled schema (a third of a second in a fresh JVM). */
    private static final class Validation {
        static final Schema SCHEMA = SafeXml.schema("/schemas/robot-program.xsd");
    }

    private RobotProgramXml() {}

    /** The binding, set up when first needed (it takes a while in a fresh JVM). */
    private static final class Binding {
        static final JAXBContext CONTEXT = createContext();
    }

    private static JAXBContext createContext() {
        try {
            return JAXBContext.newInstance(ObjectFactory.class);
        } catch (JAXBException e) {
            throw new IllegalStateException("cannot set up robot program XML binding", e);
        }
    }

    /**
     * Writes the program, valid against the schema. The binding classes are generated from the
     * schema, so the structure, the enumerations and the fixed values cannot be wrong, and
     * {@link RobotProgram} refuses null names; what is left, the {@code FiniteDouble} range, at
     * least one joint and the integer ranges, is checked here instead of validating the whole
     * document while it is written (which cost a third of {@code fresa robot}'s XML time).
     * Tests validate the written file with the schema.
     *
     * @throws IOException when the program cannot be written valid, e.g. a NaN joint value
     */
    public static void write(RobotProgram p, RapidWriter.ArmGeometry arm, OutputStream out) throws IOException {
        RobotProgramType x = toXml(p, arm);
        String invalid = invalidity(x);
        if (invalid != null) {
            throw new IOException("cannot write the robot program XML: " + invalid);
        }
        if (plainStrings(x)) {
            writeDirect(x, out);
        } else {
            marshal(x, out);
        }
    }

    /** The document as the binding writes it (formatted, UTF-8). */
    static void marshal(RobotProgramType x, OutputStream out) throws IOException {
        try {
            Marshaller m = Binding.CONTEXT.createMarshaller();
            m.setProperty(Marshaller.JAXB_FORMATTED_OUTPUT, Boolean.TRUE);
            m.setProperty(Marshaller.JAXB_ENCODING, "UTF-8");
            m.marshal(new ObjectFactory().createRobotProgram(x), out);
        } catch (JAXBException e) {
            throw new IOException("cannot write the robot program XML: " + e.getMessage(), e);
        }
    }

    /**
     * Whether every text of the document is printable ASCII that needs no escaping: then
     * {@link #writeDirect} writes the bytes the binding would; anything else goes through the
     * binding, whose escaping is the reference.
     */
    static boolean plainStrings(RobotProgramType x) {
        if (!plain(x.getName())
                || !plain(x.getResource().getRobotName())
                || !plain(x.getActivityList().getTask())) {
            return false;
        }
        for (JointDefinitionType d : x.getResource().getJointDefinition()) {
            if (!plain(d.getJointName())) {
                return false;
            }
        }
        for (ActivityType a : x.getActivityList().getActivity()) {
            if (!plain(a.getWorkingstep())
                    || !plain(a.getRole())
                    || !plain(a.getActivityName())
                    || !plain(a.getMotionType())
                    || !plain(a.getCartesianTarget().getConfig())) {
                return false;
            }
            for (JointValueType v : a.getJointTarget().getJoint()) {
                if (!plain(v.getJointName())) {
                    return false;
                }
            }
        }
        return true;
    }

    private static boolean plain(String s) {
        if (s == null) {
            return false;
        }
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c < 0x20 || c > 0x7e || c == '&' || c == '<' || c == '>' || c == '"') {
                return false;
            }
        }
        return true;
    }

    /**
     * The binding's formatted output written straight from the document: in a fresh JVM the
     * binding's set-up and marshalling of example 2's 8.8 MB took most of {@code fresa robot}'s
     * XML time. Same bytes (a test compares them): 4-space indent, schema order, doubles as
     * {@link String#valueOf(double)} (the binding's xs:double), only for plain strings. It took
     * program.xml from 1.1 s to 0.2 s of an output thread's time in {@code fresa robot} on example
     * 2 (docs/performance.md, "Fast paths"), whose whole process takes 1.9 s against a goal of 3.
     */
    static void writeDirect(RobotProgramType x, OutputStream out) throws IOException {
        // every character is printable ASCII (plainStrings, numbers), so its Latin-1 bytes are
        // its UTF-8 bytes: a builder's text goes out by array copies, without a charset encoder
        StringBuilder sb = new StringBuilder(1 << 16);
        sb.append("<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n");
        sb.append("<RobotProgram xmlns=\"urn:fresa:robot-program:1\" version=\"")
                .append(x.getVersion())
                .append("\" name=\"")
                .append(x.getName())
                .append("\">\n");
        sb.append("    <Resource RobotName=\"")
                .append(x.getResource().getRobotName())
                .append("\">\n");
        for (JointDefinitionType d : x.getResource().getJointDefinition()) {
            sb.append("        <JointDefinition JointName=\"")
                    .append(d.getJointName())
                    .append("\" JointType=\"")
                    .append(d.getJointType().value())
                    .append("\" Units=\"")
                    .append(d.getUnits().value())
                    .append("\" DOFNumber=\"")
                    .append(d.getDOFNumber())
                    .append("\" Min=\"")
                    .append(d.getMin())
                    .append("\" Max=\"")
                    .append(d.getMax())
                    .append("\"/>\n");
        }
        for (ToolFrameType t : x.getResource().getToolFrame()) {
            sb.append("        <ToolFrame Number=\"")
                    .append(t.getNumber())
                    .append("\" X=\"")
                    .append(t.getX())
                    .append("\" Y=\"")
                    .append(t.getY())
                    .append("\" Z=\"")
                    .append(t.getZ())
                    .append("\" Q1=\"")
                    .append(t.getQ1())
                    .append("\" Q2=\"")
                    .append(t.getQ2())
                    .append("\" Q3=\"")
                    .append(t.getQ3())
                    .append("\" Q4=\"")
                    .append(t.getQ4())
                    .append("\"/>\n");
        }
        sb.append("    </Resource>\n");
        List<ActivityType> activities = x.getActivityList().getActivity();
        if (activities.isEmpty()) {
            sb.append("    <ActivityList Task=\"")
                    .append(x.getActivityList().getTask())
                    .append("\"/>\n");
        } else {
            sb.append("    <ActivityList Task=\"")
                    .append(x.getActivityList().getTask())
                    .append("\">\n");
            for (ActivityType a : activities) {
                activity(a, sb);
                if (sb.length() > (1 << 16) - 4096) {
                    out.write(sb.toString().getBytes(StandardCharsets.ISO_8859_1));
                    sb.setLength(0);
                }
            }
            sb.append("    </ActivityList>\n");
        }
        sb.append("</RobotProgram>\n");
        out.write(sb.toString().getBytes(StandardCharsets.ISO_8859_1));
    }

    private static void activity(ActivityType a, StringBuilder sb) {
        sb.append("        <Activity ActivityType=\"")
                .append(a.getActivityType())
                .append("\" Index=\"")
                .append(a.getIndex())
                .append("\" Workingstep=\"")
                .append(a.getWorkingstep())
                .append("\" Role=\"")
                .append(a.getRole())
                .append(a.getTool() == null ? "\">\n" : "\" Tool=\"" + a.getTool() + "\">\n");
        sb.append("            <ActivityName>").append(a.getActivityName()).append("</ActivityName>\n");
        sb.append("            <MotionType>").append(a.getMotionType()).append("</MotionType>\n");
        sb.append("            <JointTarget>\n");
        for (JointValueType v : a.getJointTarget().getJoint()) {
            sb.append("                <Joint JointName=\"")
                    .append(v.getJointName())
                    .append("\" JointType=\"")
                    .append(v.getJointType().value())
                    .append("\" Units=\"")
                    .append(v.getUnits().value())
                    .append("\" DOFNumber=\"")
                    .append(v.getDOFNumber())
                    .append("\">\n");
            sb.append("                    <JointValue>")
                    .append(v.getJointValue())
                    .append("</JointValue>\n");
            sb.append("                </Joint>\n");
        }
        sb.append("            </JointTarget>\n");
        CartesianTargetType c = a.getCartesianTarget();
        CartesianTargetType.Position pos = c.getPosition();
        sb.append("            <CartesianTarget>\n");
        sb.append("                <Position X=\"")
                .append(pos.getX())
                .append("\" Y=\"")
                .append(pos.getY())
                .append("\" Z=\"")
                .append(pos.getZ())
                .append("\" Units=\"")
                .append(pos.getUnits())
                .append("\"/>\n");
        CartesianTargetType.Orientation o = c.getOrientation();
        sb.append("                <Orientation Q1=\"")
                .append(o.getQ1())
                .append("\" Q2=\"")
                .append(o.getQ2())
                .append("\" Q3=\"")
                .append(o.getQ3())
                .append("\" Q4=\"")
                .append(o.getQ4())
                .append("\" Roll=\"")
                .append(o.getRoll())
                .append("\" Pitch=\"")
                .append(o.getPitch())
                .append("\" Yaw=\"")
                .append(o.getYaw())
                .append("\" Units=\"")
                .append(o.getUnits())
                .append("\"/>\n");
        sb.append("                <Config>").append(c.getConfig()).append("</Config>\n");
        sb.append("            </CartesianTarget>\n");
        MoveAttributesType mv = a.getMoveAttributes();
        sb.append("            <MoveAttributes>\n");
        sb.append("                <MotionBasis Criterion=\"")
                .append(mv.getMotionBasis().getCriterion())
                .append("\" Units=\"")
                .append(mv.getMotionBasis().getUnits())
                .append("\">")
                .append(mv.getMotionBasis().getValue())
                .append("</MotionBasis>\n");
        sb.append("                <Rounding Units=\"")
                .append(mv.getRounding().getUnits())
                .append("\">")
                .append(mv.getRounding().getValue())
                .append("</Rounding>\n");
        if (mv.getDwell() != null) {
            sb.append("                <Dwell Units=\"")
                    .append(mv.getDwell().getUnits())
                    .append("\">")
                    .append(mv.getDwell().getValue())
                    .append("</Dwell>\n");
        }
        if (mv.getSpindle() != null) {
            sb.append("                <Spindle Units=\"")
                    .append(mv.getSpindle().getUnits())
                    .append("\">")
                    .append(mv.getSpindle().getValue())
                    .append("</Spindle>\n");
        }
        sb.append("            </MoveAttributes>\n");
        sb.append("        </Activity>\n");
    }

    /**
     * Reads a program written by {@link #write} (or by hand to the same schema).
     *
     * @throws CamInputException when the file is not well-formed or not valid, with line and column
     */
    public static RobotProgram read(Path file) throws CamInputException {
        String name = file.toString();
        try (InputStream in = Files.newInputStream(file)) {
            Unmarshaller u = Binding.CONTEXT.createUnmarshaller();
            u.setSchema(Validation.SCHEMA);
            JAXBElement<RobotProgramType> root = u.unmarshal(SafeXml.source(in, file), RobotProgramType.class);
            try {
                return fromXml(root.getValue());
            } catch (IllegalArgumentException | ArithmeticException e) {
                // schema-valid but inconsistent: joint counts, indices or orientations that do not fit
                throw new CamInputException(name, "not a consistent robot program: " + e.getMessage());
            }
        } catch (IOException e) {
            throw new CamInputException(name, "cannot read (" + e.getMessage() + ")");
        } catch (UnmarshalException e) {
            Throwable c = e.getLinkedException() != null ? e.getLinkedException() : e.getCause();
            if (c instanceof SAXParseException spe) {
                throw new CamInputException(
                        name,
                        Math.max(0, spe.getLineNumber()),
                        Math.max(0, spe.getColumnNumber()),
                        "expected a robot program as schemas/robot-program.xsd describes: " + spe.getMessage());
            }
            throw new CamInputException(name, "not a robot program: " + e.getMessage());
        } catch (JAXBException | SAXException | ParserConfigurationException e) {
            throw new CamInputException(name, "not a robot program: " + e.getMessage());
        }
    }

    /** What makes the document invalid against the schema beyond the binding's types, or null. */
    static String invalidity(RobotProgramType x) {
        List<JointDefinitionType> defs = x.getResource().getJointDefinition();
        if (defs.isEmpty()) {
            return "a robot program needs at least one joint";
        }
        for (JointDefinitionType d : defs) {
            if (!finite(d.getMin()) || !finite(d.getMax())) {
                return "joint " + d.getJointName() + " has the limits " + d.getMin() + ", " + d.getMax();
            }
        }
        for (ToolFrameType t : x.getResource().getToolFrame()) {
            for (double v : new double[] {t.getX(), t.getY(), t.getZ(), t.getQ1(), t.getQ2(), t.getQ3(), t.getQ4()}) {
                if (!finite(v)) {
                    return "tool " + t.getNumber() + " has the number " + v + " in its frame";
                }
            }
        }
        for (ActivityType a : x.getActivityList().getActivity()) {
            if (a.getIndex().signum() < 0) {
                return "motion index " + a.getIndex() + " is negative";
            }
            for (JointValueType v : a.getJointTarget().getJoint()) {
                if (!finite(v.getJointValue())) {
                    return "motion " + a.getIndex() + " has the joint value " + v.getJointValue();
                }
            }
            CartesianTargetType.Position pos = a.getCartesianTarget().getPosition();
            CartesianTargetType.Orientation o = a.getCartesianTarget().getOrientation();
            MoveAttributesType mv = a.getMoveAttributes();
            double[] numbers = {
                pos.getX(),
                pos.getY(),
                pos.getZ(),
                o.getQ1(),
                o.getQ2(),
                o.getQ3(),
                o.getQ4(),
                o.getRoll(),
                o.getPitch(),
                o.getYaw(),
                mv.getMotionBasis().getValue(),
                mv.getRounding().getValue(),
                mv.getDwell() == null ? 0 : mv.getDwell().getValue()
            };
            for (double v : numbers) {
                if (!finite(v)) {
                    return "motion " + a.getIndex() + " has the number " + v + " in its target or move attributes";
                }
            }
        }
        return null;
    }

    /** The schema's FiniteDouble: -1e300 to 1e300, which NaN is not in. */
    private static boolean finite(double v) {
        return v >= -1e300 && v <= 1e300;
    }

    static RobotProgramType toXml(RobotProgram p, RapidWriter.ArmGeometry arm) {
        RobotProgramType x = new RobotProgramType();
        x.setVersion(VERSION);
        x.setName(p.programName());
        ResourceType r = new ResourceType();
        r.setRobotName(p.robotName());
        for (int i = 0; i < p.joints().size(); i++) {
            RobotProgram.Joint j = p.joints().get(i);
            JointDefinitionType d = new JointDefinitionType();
            d.setJointName(j.name());
            d.setJointType(type(j.type()));
            d.setUnits(units(j.type()));
            d.setDOFNumber(BigInteger.valueOf(i + 1));
            d.setMin(j.minValue());
            d.setMax(j.maxValue());
            r.getJointDefinition().add(d);
        }
        for (RobotProgram.ToolFrame t : p.tools()) {
            ToolFrameType f = new ToolFrameType();
            f.setNumber(BigInteger.valueOf(t.number()));
            Vec3 at = t.tcp().translationPart();
            Quaternion q = Quaternion.of(t.tcp());
            f.setX(at.x());
            f.setY(at.y());
            f.setZ(at.z());
            f.setQ1(q.w());
            f.setQ2(q.x());
            f.setQ3(q.y());
            f.setQ4(q.z());
            r.getToolFrame().add(f);
        }
        x.setResource(r);
        ActivityListType list = new ActivityListType();
        list.setTask(p.programName());
        for (RobotProgram.Motion m : p.motions()) {
            ActivityType a = new ActivityType();
            a.setActivityType("DNBRobotMotionActivity");
            a.setIndex(BigInteger.valueOf(m.index()));
            a.setWorkingstep(m.workingstep());
            a.setRole(m.role() == RobotProgram.PointRole.PART ? "part" : "relink");
            a.setTool(BigInteger.valueOf(p.toolOf(m.workingstep()).number()));
            a.setActivityName("Move " + m.index());
            a.setMotionType(m.type() == RobotProgram.MotionType.JOINT ? "Joint" : "Linear");
            JointTargetType jt = new JointTargetType();
            for (int i = 0; i < p.joints().size(); i++) {
                RobotProgram.Joint j = p.joints().get(i);
                JointValueType v = new JointValueType();
                v.setJointName(j.name());
                v.setJointType(type(j.type()));
                v.setUnits(units(j.type()));
                v.setDOFNumber(BigInteger.valueOf(i + 1));
                v.setJointValue(m.joint(i));
                jt.getJoint().add(v);
            }
            a.setJointTarget(jt);
            CartesianTargetType c = new CartesianTargetType();
            CartesianTargetType.Position pos = new CartesianTargetType.Position();
            Vec3 t = m.target().translationPart();
            pos.setX(t.x());
            pos.setY(t.y());
            pos.setZ(t.z());
            pos.setUnits("mm");
            c.setPosition(pos);
            CartesianTargetType.Orientation o = new CartesianTargetType.Orientation();
            Quaternion q = Quaternion.of(m.target());
            o.setQ1(q.w());
            o.setQ2(q.x());
            o.setQ3(q.y());
            o.setQ4(q.z());
            Vec3 rpy = m.target().zyxAnglesDeg();
            o.setRoll(rpy.x());
            o.setPitch(rpy.y());
            o.setYaw(rpy.z());
            o.setUnits("deg");
            c.setOrientation(o);
            c.setConfig(config(m, arm));
            a.setCartesianTarget(c);
            MoveAttributesType mv = new MoveAttributesType();
            MoveAttributesType.MotionBasis b = new MoveAttributesType.MotionBasis();
            b.setCriterion("Speed");
            b.setUnits("mm/s");
            b.setValue(m.speedMmPerS());
            mv.setMotionBasis(b);
            MoveAttributesType.Rounding rd = new MoveAttributesType.Rounding();
            rd.setUnits("mm");
            rd.setValue(m.zoneMm());
            mv.setRounding(rd);
            if (m.dwellS() > 0) {
                MoveAttributesType.Dwell dw = new MoveAttributesType.Dwell();
                dw.setUnits("s");
                dw.setValue(m.dwellS());
                mv.setDwell(dw);
            }
            if (m.spindleRpm() > 0) {
                MoveAttributesType.Spindle sp = new MoveAttributesType.Spindle();
                sp.setUnits("rpm");
                sp.setValue(m.spindleRpm());
                mv.setSpindle(sp);
            }
            a.setMoveAttributes(mv);
            list.getActivity().add(a);
        }
        x.setActivityList(list);
        return x;
    }

    /** ABB-style confdata "cf1 cf4 cf6 cfx" for six-joint arms, else the signs of the joints. */
    static String config(RobotProgram.Motion m, RapidWriter.ArmGeometry arm) {
        if (m.jointValues().size() == 6) {
            return RapidWriter.confdata(m, arm).toString().replace(',', ' ');
        }
        StringBuilder sb = new StringBuilder();
        for (double v : m.jointValues()) {
            sb.append(v < 0 ? '-' : '+');
        }
        return sb.toString();
    }

    private static JointTypeType type(RobotProgram.JointType t) {
        return t == RobotProgram.JointType.REVOLUTE ? JointTypeType.ROTATIONAL : JointTypeType.TRANSLATIONAL;
    }

    private static JointUnitsType units(RobotProgram.JointType t) {
        return t == RobotProgram.JointType.REVOLUTE ? JointUnitsType.DEG : JointUnitsType.MM;
    }

    static RobotProgram fromXml(RobotProgramType x) {
        List<RobotProgram.Joint> joints = new ArrayList<>();
        for (JointDefinitionType d : x.getResource().getJointDefinition()) {
            joints.add(new RobotProgram.Joint(
                    d.getJointName(),
                    d.getJointType() == JointTypeType.ROTATIONAL
                            ? RobotProgram.JointType.REVOLUTE
                            : RobotProgram.JointType.PRISMATIC,
                    d.getMin(),
                    d.getMax()));
        }
        List<RobotProgram.Motion> motions = new ArrayList<>();
        for (ActivityType a : x.getActivityList().getActivity()) {
            List<Double> values = new ArrayList<>();
            for (JointValueType v : a.getJointTarget().getJoint()) {
                values.add(v.getJointValue());
            }
            CartesianTargetType c = a.getCartesianTarget();
            CartesianTargetType.Orientation o = c.getOrientation();
            Transform3 r = new Quaternion(o.getQ1(), o.getQ2(), o.getQ3(), o.getQ4()).toTransform();
            Transform3 target = new Transform3(
                    r.r00(),
                    r.r01(),
                    r.r02(),
                    r.r10(),
                    r.r11(),
                    r.r12(),
                    r.r20(),
                    r.r21(),
                    r.r22(),
                    c.getPosition().getX(),
                    c.getPosition().getY(),
                    c.getPosition().getZ());
            motions.add(new RobotProgram.Motion(
                    a.getIndex().intValueExact(),
                    a.getWorkingstep(),
                    "Joint".equals(a.getMotionType()) ? RobotProgram.MotionType.JOINT : RobotProgram.MotionType.LINEAR,
                    "part".equals(a.getRole()) ? RobotProgram.PointRole.PART : RobotProgram.PointRole.RELINK,
                    values,
                    target,
                    a.getMoveAttributes().getMotionBasis().getValue(),
                    a.getMoveAttributes().getRounding().getValue(),
                    a.getMoveAttributes().getDwell() == null
                            ? 0
                            : a.getMoveAttributes().getDwell().getValue(),
                    a.getMoveAttributes().getSpindle() == null
                            ? 0
                            : a.getMoveAttributes().getSpindle().getValue()));
        }
        List<RobotProgram.ToolFrame> tools = new ArrayList<>();
        for (ToolFrameType t : x.getResource().getToolFrame()) {
            List<String> steps = new ArrayList<>();
            for (ActivityType a : x.getActivityList().getActivity()) {
                if (a.getTool() != null && a.getTool().equals(t.getNumber()) && !steps.contains(a.getWorkingstep())) {
                    steps.add(a.getWorkingstep());
                }
            }
            Transform3 r = new Quaternion(t.getQ1(), t.getQ2(), t.getQ3(), t.getQ4()).toTransform();
            tools.add(new RobotProgram.ToolFrame(
                    t.getNumber().intValueExact(),
                    new Transform3(
                            r.r00(), r.r01(), r.r02(), r.r10(), r.r11(), r.r12(), r.r20(), r.r21(), r.r22(), t.getX(),
                            t.getY(), t.getZ()),
                    steps));
        }
        if (tools.isEmpty()) {
            return new RobotProgram(x.getName(), x.getResource().getRobotName(), joints, motions);
        }
        return new RobotProgram(x.getName(), x.getResource().getRobotName(), joints, motions, tools);
    }
}
