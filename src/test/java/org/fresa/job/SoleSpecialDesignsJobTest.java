package org.fresa.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fresa.dxf.DxfWriter;
import org.fresa.geom.Contour;
import org.fresa.geom.Vec2;
import org.fresa.io.OutputFolder;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A sole job names the special designs F-J of the figure library; LOGO engraves a DXF drawing. */
class SoleSpecialDesignsJobTest {

    @Test
    @org.fresa.testing.InterpreterCheck
    void aJobWithEverySpecialDesignWritesCheckedProgramsAndReadsBack(@TempDir Path dir) throws Exception {
        // a drawing of the size number's frame: a rectangle 30 x 12 and an inner one
        Path dxf = dir.resolve("mark.dxf");
        Files.writeString(
                dxf,
                DxfWriter.write(
                        List.of(
                                Contour.polygon(
                                        List.of(Vec2.of(0, 0), Vec2.of(30, 0), Vec2.of(30, 12), Vec2.of(0, 12))),
                                Contour.polygon(List.of(Vec2.of(3, 3), Vec2.of(27, 3), Vec2.of(27, 9), Vec2.of(3, 9)))),
                        "0"));
        String designs = """
                <design name="parallelograms" tool="bit3.5" rule="position">
                  <figure macro="PARAL" params="XO=-60,YO=-30,A=8,B=8,ANG=60,NA=12,NB=6"/>
                </design>
                <design name="honeycomb" tool="bit3.5" rule="position">
                  <figure macro="COLMEIA" params="XO=-55,YO=60,S=6,NX=10,NY=6"/>
                </design>
                <design name="pyramids" tool="bit3.5" rule="position">
                  <figure macro="PIRAM" params="XO=-60,YO=120,P=6,ANG=45,N1=16,N2=16"/>
                </design>
                <design name="stitching" tool="bit3.5" rule="position">
                  <figure macro="TEXTURA" params="XO=-50,YO=200,L=80,P=3,ANG=0,N=5,DASH=4,GAP=2"/>
                </design>
                <design name="size mark" tool="bit3.5" rule="position">
                  <figure macro="LOGO" params="X=-30,Y=20,H=12" file="%s"/>
                </design>
                """.formatted(dxf.toAbsolutePath());
        String sample = Files.readString(Path.of("samples/jobs/sole-men40.xml"));
        int from = sample.indexOf("    <!-- heel circle detail");
        int to = sample.indexOf("  </sole>");
        String xml = sample.substring(0, from) + designs + sample.substring(to);
        xml = xml.replace("sizes=\"38-42\"", "sizes=\"40\"")
                .replace(
                        "outline=\"../sole/men40.contour\"",
                        "outline=\"" + Path.of("samples/sole/men40.contour").toAbsolutePath() + "\"");
        Path job = dir.resolve("special.xml");
        Files.writeString(job, xml);
        Job j = JobXml.read(job);
        TaskOutcome t = JobRunner.run(j, new OutputFolder(dir.resolve("out")), ProgressMonitor.NONE);
        assertEquals(0, t.exitStatus(), t.problems().toString());
        String right = Files.readString(dir.resolve("out/tread-40-right.ngc"));
        for (String name : List.of("parallelograms", "honeycomb", "pyramids", "stitching", "size mark")) {
            assertTrue(
                    j.sole().orElseThrow().designs().stream()
                            .anyMatch(d -> d.name().equals(name)),
                    name);
        }
        assertTrue(right.lines().filter(l -> l.startsWith("G1 ")).count() > 200, "the fields are cut");
        // the drawing is saved with the job, relative to it
        Path copy = dir.resolve("copy.xml");
        JobXml.write(j, copy);
        assertTrue(Files.readString(copy).contains("file=\"mark.dxf\""));
        assertEquals(
                j.sole().orElseThrow().designs(),
                JobXml.read(copy).sole().orElseThrow().designs());
        org.junit.jupiter.api.Assumptions.assumeTrue(org.fresa.post.Rs274.available(), org.fresa.post.Rs274.whyNot());
        for (String f : List.of("tread-40-right.ngc", "tread-40-left.ngc")) {
            org.fresa.post.Rs274.Result r =
                    org.fresa.post.Rs274.run(dir.resolve("out").resolve(f), 3.5);
            assertEquals(0, r.exitStatus(), f + ": " + org.fresa.post.Rs274.log(r));
        }
    }

    @Test
    void aLogoWithoutItsDrawingIsRefused(@TempDir Path dir) throws Exception {
        JobSettings.SoleSettings s =
                JobXml.read(Path.of("samples/jobs/sole-men40.xml")).sole().orElseThrow();
        JobSettings.SoleDesign logo = new JobSettings.SoleDesign(
                "mark",
                "bit3.5",
                org.fresa.sole.SizeRule.POSITION,
                false,
                org.fresa.sole.PatternKind.SINGLE,
                1,
                1,
                0,
                0,
                0,
                0,
                0,
                0,
                List.of(),
                List.of(new JobSettings.SoleFigure("LOGO", "X=0,Y=0,H=10")),
                List.of());
        CamInputException e = org.junit.jupiter.api.Assertions.assertThrows(
                CamInputException.class, () -> SoleService.plan(s.withDesigns(List.of(logo)), "job.xml"));
        assertTrue(e.getMessage().contains("file attribute"), e.getMessage());
    }
}
