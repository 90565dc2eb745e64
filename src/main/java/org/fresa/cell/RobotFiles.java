package org.fresa.cell;

import jakarta.xml.bind.JAXBContext;
import jakarta.xml.bind.JAXBElement;
import jakarta.xml.bind.JAXBException;
import jakarta.xml.bind.Marshaller;
import jakarta.xml.bind.UnmarshalException;
import jakarta.xml.bind.Unmarshaller;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.validation.Schema;
import org.fresa.cell.robotxml.FrameType;
import org.fresa.cell.robotxml.JointType;
import org.fresa.cell.robotxml.LimitType;
import org.fresa.cell.robotxml.ObjectFactory;
import org.fresa.cell.robotxml.RobotType;
import org.fresa.cell.robotxml.SerialType;
import org.fresa.cell.robotxml.TriceptType;
import org.fresa.geom.Transform3;
import org.fresa.io.AtomicFiles;
import org.fresa.io.SafeXml;
import org.fresa.io.XmlLines;
import org.fresa.kin.DenavitHartenbergChain;
import org.fresa.kin.DhExpression;
import org.fresa.kin.DhJoint;
import org.fresa.kin.JointLimit;
import org.fresa.kin.Robot;
import org.fresa.kin.Robots;
import org.fresa.kin.SerialRobot;
import org.fresa.kin.TriceptRobot;
import org.fresa.model.CamInputException;
import org.fresa.model.ExactDecimal;
import org.fresa.model.FileChecks;
import org.fresa.setting.SettingRange;
import org.fresa.setting.SettingRanges.RobotFile;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/**
 * Robots by name or from files (schemas/robot.xsd), and their parameters as JSON-able maps for
 * {@code fresa robots}.
 */
public final class RobotFiles {

    /** The highest joint number a cell may name (the reader then checks it is the cell's own joint). */
    private static final int MAX_JOINT = 99;

    private RobotFiles() {}

    /** A built-in robot name ({@code irb140}, {@code adept-one}, {@code tricept806}) or a robot file. */
    public static Robot load(String nameOrFile) throws CamInputException {
        var builtIn = Robots.byName(nameOrFile);
        if (builtIn.isPresent()) {
            return builtIn.get();
        }
        Path p = Path.of(nameOrFile);
        if (Files.exists(p)) {
            FileChecks.requireInput(p, "a robot file", FileChecks.MAX_TEXT_FILE_BYTES);
        } else {
            throw new CamInputException(
                    nameOrFile, "neither a built-in robot (irb140, adept-one, tricept806) nor a" + " robot file");
        }
        return read(p);
    }

    /** Reads and validates a robot file. */
    public static Robot read(Path file) throws CamInputException {
        String name = file.toString();
        FileChecks.requireInput(file, "a robot file", FileChecks.MAX_TEXT_FILE_BYTES);
        RobotType xml;
        try (InputStream in = Files.newInputStream(file)) {
            Unmarshaller u = Holder.CONTEXT.createUnmarshaller();
            u.setSchema(Holder.SCHEMA);
            JAXBElement<RobotType> root = u.unmarshal(SafeXml.source(in, file), RobotType.class);
            xml = root.getValue();
        } catch (IOException e) {
            throw new CamInputException(name, "cannot read the robot file (" + e.getMessage() + ")");
        } catch (UnmarshalException e) {
            Throwable c = e.getLinkedException() != null ? e.getLinkedException() : e.getCause();
            if (c instanceof SAXParseException spe) {
                throw new CamInputException(
                        name,
                        Math.max(0, spe.getLineNumber()),
                        Math.max(0, spe.getColumnNumber()),
                        "expected a robot as schemas/robot.xsd describes: " + spe.getMessage(),
                        e);
            }
            throw new CamInputException(name, "not a valid robot file: " + e.getMessage());
        } catch (JAXBException | SAXException | ParserConfigurationException e) {
            throw new CamInputException(name, "not a valid robot file: " + e.getMessage());
        }
        String description = xml.getDescription() == null ? "robot from " + file.getFileName() : xml.getDescription();
        try {
            if (xml.getSerial() != null) {
                return serial(name, xml.getName(), description, xml.getSerial());
            }
            return tricept(xml.getName(), description, xml.getTricept());
        } catch (SettingRange.OutOfRange e) {
            throw new CamInputException(
                    name,
                    XmlLines.lineOf(file, e.range().attribute(), e.value()),
                    0,
                    e.range().attribute() + ": " + e.range().problem(e.value()));
        } catch (IllegalArgumentException e) {
            throw new CamInputException(name, e.getMessage());
        }
    }

    private static SerialRobot serial(String file, String name, String description, SerialType s)
            throws CamInputException {
        List<DhJoint> joints = new ArrayList<>();
        int i = 1;
        for (JointType j : s.getJoint()) {
            boolean rev = j.getType().equals("revolute");
            String variable = rev ? j.getTheta() : j.getD();
            double offset = (rev ? RobotFile.THETA : RobotFile.D)
                    .require(variableOffset(file, i, rev ? "theta" : "d", variable));
            double a = RobotFile.A.require(number(file, i, "a", j.getA()));
            double alpha = RobotFile.ALPHA.require(number(file, i, "alpha", j.getAlpha()));
            double min = RobotFile.limit("min", rev).require(j.getMin());
            double max = RobotFile.limit("max", rev).require(j.getMax());
            if (rev) {
                joints.add(DhJoint.revolute(
                        a, alpha, RobotFile.D.require(number(file, i, "d", j.getD())), offset, min, max));
            } else {
                joints.add(DhJoint.prismatic(
                        a, alpha, offset, RobotFile.THETA.require(number(file, i, "theta", j.getTheta())), min, max));
            }
            i++;
        }
        FrameType t = s.getTool();
        Transform3 tool = t == null
                ? Transform3.IDENTITY
                : Transform3.ofXyzRpyDeg(
                        RobotFile.tool(0).require(t.getX()),
                        RobotFile.tool(1).require(t.getY()),
                        RobotFile.tool(2).require(t.getZ()),
                        RobotFile.tool(3).require(t.getRx()),
                        RobotFile.tool(4).require(t.getRy()),
                        RobotFile.tool(5).require(t.getRz()));
        int wrist = s.getWristJoint() == 0 ? -1 : s.getWristJoint() - 1;
        return new SerialRobot(name, description, new DenavitHartenbergChain(joints, Transform3.IDENTITY, tool), wrist);
    }

    private static TriceptRobot tricept(String name, String description, TriceptType t) {
        List<JointLimit> legs = joints(t.getLeg(), 1, org.fresa.kin.JointType.PRISMATIC);
        List<JointLimit> wrist = joints(t.getWrist(), 1 + legs.size(), org.fresa.kin.JointType.REVOLUTE);
        return new TriceptRobot(
                name,
                description,
                RobotFile.BASE_RADIUS.require(t.getBaseRadius()),
                RobotFile.PLATFORM_RADIUS.require(t.getPlatformRadius()),
                RobotFile.CENTRE_OFFSET.require(t.getCentreOffset()),
                RobotFile.EFFECTOR_LENGTH.require(t.getEffectorLength()),
                legs,
                wrist);
    }

    /** Joints of one type named q{@code first}, q{@code first + 1}, ... with the limits the file gives them. */
    private static List<JointLimit> joints(List<LimitType> limits, int first, org.fresa.kin.JointType type) {
        boolean revolute = type == org.fresa.kin.JointType.REVOLUTE;
        List<JointLimit> joints = new ArrayList<>();
        for (LimitType l : limits) {
            joints.add(new JointLimit(
                    "q" + (first + joints.size()),
                    type,
                    RobotFile.limit("min", revolute).require(l.getMin()),
                    RobotFile.limit("max", revolute).require(l.getMax())));
        }
        return joints;
    }

    /**
     * The offset c of joint N's variable cell, an expression equal to qN + c ("qN", "q2 - 90",
     * "q2 - 180/2"; see {@link DhExpression}).
     */
    static double variableOffset(String file, int joint, String cell, String text) throws CamInputException {
        String expected = cell + " must be q" + joint + " plus a constant (q" + joint + ", q" + joint + " - 90, ...)";
        DhExpression e;
        try {
            e = DhExpression.parse(text, MAX_JOINT);
        } catch (IllegalArgumentException ex) {
            throw new CamInputException(
                    file, "joint " + joint + ": " + expected + ", not '" + text + "': " + ex.getMessage());
        }
        if (e.coefficients().size() != 1 || e.coefficient(joint) != 1) {
            throw new CamInputException(file, "joint " + joint + ": " + expected + ", not '" + text + "'");
        }
        return e.constant();
    }

    private static double number(String file, int joint, String cell, String text) throws CamInputException {
        try {
            DhExpression e = DhExpression.parse(text, MAX_JOINT);
            if (e.isConstant()) {
                return e.constant();
            }
        } catch (IllegalArgumentException e) {
            throw new CamInputException(
                    file, "joint " + joint + ": " + cell + " must be a number, not '" + text + "': " + e.getMessage());
        }
        throw new CamInputException(file, "joint " + joint + ": " + cell + " must be a number, not '" + text + "'");
    }

    /**
     * Writes a robot as a robot file (schemas/robot.xsd) that {@link #read} and {@code --robot FILE}
     * read back as the same robot: numbers written exactly, the variable cell as "qN", "qN + c"
     * or "qN - c", the tool as x, y, z (mm) and rx, ry, rz (deg, R = Rz Ry Rx). Atomic.
     */
    public static void write(Robot robot, Path file) throws IOException {
        RobotType x = new RobotType();
        x.setName(robot.name());
        x.setVersion(1);
        x.setDescription(robot.description());
        if (robot instanceof SerialRobot s) {
            SerialType st = new SerialType();
            int i = 1;
            for (DhJoint d : s.chain().joints()) {
                JointType j = new JointType();
                boolean rev = d.type() == org.fresa.kin.JointType.REVOLUTE;
                j.setType(rev ? "revolute" : "prismatic");
                j.setA(ExactDecimal.of(d.aMm()));
                j.setAlpha(ExactDecimal.of(d.alphaDeg()));
                j.setTheta(rev ? variable(i, d.thetaDeg()) : ExactDecimal.of(d.thetaDeg()));
                j.setD(rev ? ExactDecimal.of(d.dMm()) : variable(i, d.dMm()));
                j.setMin(d.qMin());
                j.setMax(d.qMax());
                st.getJoint().add(j);
                i++;
            }
            Transform3 t = s.chain().tool();
            if (!t.equals(Transform3.IDENTITY)) {
                FrameType f = new FrameType();
                org.fresa.geom.Vec3 zyx = t.zyxAnglesDeg();
                f.setX(t.tx());
                f.setY(t.ty());
                f.setZ(t.tz());
                f.setRz(zyx.x());
                f.setRy(zyx.y());
                f.setRx(zyx.z());
                st.setTool(f);
            }
            st.setWristJoint(s.wristJoint() < 0 ? 0 : s.wristJoint() + 1);
            x.setSerial(st);
        } else if (robot instanceof TriceptRobot t) {
            TriceptType tt = new TriceptType();
            tt.setBaseRadius(t.baseRadiusMm());
            tt.setPlatformRadius(t.platformRadiusMm());
            tt.setCentreOffset(t.centreOffsetMm());
            tt.setEffectorLength(t.effectorLengthMm());
            for (JointLimit l : t.legs()) {
                tt.getLeg().add(limit(l));
            }
            for (JointLimit l : t.wrist()) {
                tt.getWrist().add(limit(l));
            }
            x.setTricept(tt);
        }
        AtomicFiles.write(file, out -> {
            try {
                Marshaller m = Holder.CONTEXT.createMarshaller();
                m.setProperty(Marshaller.JAXB_FORMATTED_OUTPUT, Boolean.TRUE);
                m.setProperty(Marshaller.JAXB_ENCODING, "UTF-8");
                m.setSchema(Holder.SCHEMA);
                m.marshal(new ObjectFactory().createRobot(x), out);
            } catch (JAXBException e) {
                throw new IOException("cannot write the robot: " + e.getMessage(), e);
            }
        });
    }

    private static String variable(int joint, double offset) {
        String q = "q" + joint;
        if (offset == 0) {
            return q;
        }
        return q + (offset > 0 ? " + " : " - ") + ExactDecimal.of(Math.abs(offset));
    }

    private static LimitType limit(JointLimit l) {
        LimitType t = new LimitType();
        t.setMin(l.min());
        t.setMax(l.max());
        return t;
    }

    /** A robot's parameters for {@code fresa robots --json}. */
    public static Map<String, Object> describe(Robot r) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("name", r.name());
        m.put("description", r.description());
        m.put("dof", r.dof());
        List<Object> joints = new ArrayList<>();
        int i = 0;
        for (JointLimit l : r.joints()) {
            Map<String, Object> j = new LinkedHashMap<>();
            j.put("name", l.name());
            j.put("type", l.type() == org.fresa.kin.JointType.REVOLUTE ? "revolute" : "prismatic");
            j.put("unit", l.type().unit());
            j.put("min", l.min());
            j.put("max", l.max());
            if (r instanceof SerialRobot s) {
                DhJoint d = s.chain().joints().get(i);
                j.put("a_mm", d.aMm());
                j.put("alpha_deg", d.alphaDeg());
                j.put(d.type() == org.fresa.kin.JointType.REVOLUTE ? "d_mm" : "d_offset_mm", d.dMm());
                j.put(d.type() == org.fresa.kin.JointType.REVOLUTE ? "theta_offset_deg" : "theta_deg", d.thetaDeg());
            }
            joints.add(j);
            i++;
        }
        m.put("joints", joints);
        if (r instanceof TriceptRobot t) {
            m.put("base_radius_mm", t.baseRadiusMm());
            m.put("platform_radius_mm", t.platformRadiusMm());
            m.put("centre_offset_mm", t.centreOffsetMm());
            m.put("effector_length_mm", t.effectorLengthMm());
        }
        if (r instanceof SerialRobot s && !s.chain().tool().equals(Transform3.IDENTITY)) {
            Transform3 tool = s.chain().tool();
            m.put("tool_mm", List.of(tool.tx(), tool.ty(), tool.tz()));
        }
        return m;
    }

    /** All built-in robots described. */
    public static Map<String, Object> describeBuiltIns() {
        List<Object> list = new ArrayList<>();
        for (Robot r : Robots.all()) {
            list.add(describe(r));
        }
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("robots", list);
        return m;
    }

    /** Lazily built, so that commands that never read robot files do not pay for JAXB. */
    private static final class Holder {
        static final Schema SCHEMA = SafeXml.schema("/schemas/robot.xsd");
        static final JAXBContext CONTEXT = createContext();

        private static JAXBContext createContext() {
            try {
                return JAXBContext.newInstance(ObjectFactory.class);
            } catch (JAXBException e) {
                throw new IllegalStateException("cannot set up robot XML binding", e);
            }
        }
    }
}
