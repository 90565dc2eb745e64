package org.fresa.pocket;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.stream.Stream;
import org.fresa.geom.Contour;
import org.fresa.geom.Tolerance;
import org.fresa.model.CamInputException;
import org.fresa.model.ContourFile;
import org.fresa.model.Toolpath;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.locationtech.jts.geom.Geometry;

/**
 * Random line/arc outlines ({@link PocketCleanUpTest#pocket}, {@code new Random(7)}) whose last
 * events come within a few tolerances of one another. The recognition used to refuse them with
 * "found no event": a division following a cancellation by less than ten tolerances was dropped
 * (so the element between the pair vanished on its own and joined them at the far junction,
 * turning the subcontour inside out), and an area whose last elements meet at one point, met one
 * by one within the tolerance, left a subcontour with no area and no further event.
 */
class RecognitionRandomOutlinesTest {

    static final Tolerance TOL = new Tolerance(1e-6, 1e-9);

    static Stream<Arguments> outlines() {
        return Stream.of(
                Arguments.of("pocket 20", """
                    contour
                    move 85.334246483019290 41.085695286569630
                    arc 42.262709235634960 29.714227316419638 86.378481028108940 23.528252550603010 cw
                    line 63.637047201426010 22.661144162006007
                    arc 63.103040696067540 46.641976062936690 52.051795145248630 25.352649314916560 cw
                    line 30.982241168873170 29.374936144513470
                    arc 26.688469696629163 45.403288137548174 43.095269923711680 42.921061843053500 ccw
                    line 41.531984163204870 60.923006160001270
                    line 64.976091779116690 71.062212607346940
                    arc 37.295639815891720 48.980176804881760 72.597172683615820 51.741608183488410 cw
                    line 85.334246483019290 41.085695286569630
                    """),
                Arguments.of("pocket 107", """
                    contour
                    move 88.253096590985220 43.978909437228175
                    line 78.142985208460130 29.178179531282165
                    arc 80.939006810413830 15.183968076411285 67.726563078477230 20.577206590758678 ccw
                    arc 52.583062083438070 35.494355461575694 49.098855637842020 14.525157616514090 cw
                    arc 67.632206505753760 54.551121835952740 31.560648780691720 29.165975994803333 cw
                    line 41.745578157748760 44.878290987281170
                    arc 23.759459118391450 52.053619429624010 40.365409353792830 62.014956344556590 ccw
                    arc 43.468275102943370 87.498833326911150 59.475164452466494 67.428077106450620 ccw
                    line 74.252764663080650 58.113955003475500
                    arc 93.939864641836730 63.612453781599080 88.253096590985220 43.978909437228175 ccw
                    """),
                Arguments.of("pocket 211", """
                    contour
                    move 90.640767237021350 44.255423331746800
                    line 85.466504186507680 20.721373484522513
                    line 66.207779852834250 16.592337116633715
                    arc 57.503813944060326 33.487096489909790 49.368107283484000 16.311468584210030 cw
                    line 37.020173213104220 26.895659021175840
                    line 34.577529594842170 47.173559405785230
                    arc 56.012432633136264 17.739713818040386 50.917955291081290 53.793182929286320 cw
                    line 62.430487150523130 58.908531602063730
                    arc 65.353848426317700 27.008420182362574 75.563851085511630 57.371539182844330 cw
                    line 90.640767237021350 44.255423331746800
                    """),
                Arguments.of("pocket 605", """
                    contour
                    move 88.349700917669720 43.701546835343890
                    arc 104.97154954844920 15.492026072350146 73.294054430920950 23.774490479837493 ccw
                    arc 67.718194314943820 7.5227655908152130 57.890210850722504 21.616009324193390 ccw
                    arc 47.019567635276450 -6.7294823661710410 38.298703813868670 22.349450167443450 ccw
                    line 35.716709380758530 49.839381228514910
                    line 51.906247291544894 55.643761108791935
                    arc 72.120944838133280 25.814639717527584 74.640185767356170 61.759930160301295 cw
                    arc 67.016559477382260 41.739077761684540 88.349700917669720 43.701546835343890 cw
                    """),
                Arguments.of("pocket 1092", """
                    contour
                    move 77.708142830480840 42.165023761397165
                    arc 52.055367960427944 33.254180662309984 78.067569387682950 25.454606303533760 cw
                    arc 62.526814293823110 34.849857110165570 63.245970953716410 16.704096715368740 cw
                    arc 73.856588289135540 55.887087265938966 47.450337082698084 25.055255566422750 cw
                    line 43.750705815922650 37.006739981293460
                    arc 59.887228679350570 40.953171023300946 46.746232895143480 51.115646995754894 cw
                    line 54.602363407690680 64.739068655953660
                    arc 60.455793931582190 41.000056645492060 77.476968957263610 58.552348258725470 cw
                    line 77.708142830480840 42.165023761397165
                    """),
                Arguments.of("pocket 1135", """
                    contour
                    move 90.648407615511900 44.301263887940720
                    arc 32.797342947773450 48.432444323442660 84.011651757040110 21.212839106419377 cw
                    line 63.875983560326446 16.233321751284755
                    line 49.318757364872525 25.012816307516182
                    line 28.553049767325195 39.915045893546530
                    arc 1.1629282399936294 64.417506701750600 37.436747008906000 58.518403815745906 ccw
                    line 57.160730180221684 56.152520621341935
                    arc 61.236179934004820 45.398620143341134 69.141455795042460 53.751001824469725 cw
                    line 90.648407615511900 44.301263887940720
                    """),
                Arguments.of("pocket 1175", """
                    contour
                    move 90.048433248507930 44.004334133426404
                    line 76.985728741479020 21.120109389773194
                    arc 55.863381105717480 72.099464774346560 50.724407238343560 17.157320725692628 cw
                    line 38.626115469171550 35.778910853040410
                    line 44.455823942167120 59.219554739080840
                    line 67.485212655774550 61.156915627230560
                    line 90.048433248507930 44.004334133426404
                    """),
                Arguments.of("pocket 1506", """
                    contour
                    move 88.645319635617880 42.340516325827230
                    line 82.340459155708230 22.373015669251828
                    line 62.015338318836480 23.038880538941090
                    arc 66.367450594785310 -15.004259806714465 43.306866664710356 15.564202330358750 ccw
                    arc 84.017995047652620 50.595618559102704 31.437475853725978 39.646413176928870 cw
                    line 42.826335975588705 56.345925184567510
                    arc 56.724617748751996 46.249410669632950 55.291107890847880 63.368023086643240 cw
                    arc 60.193959252259670 33.543996325923760 75.702651689408140 59.486066069607330 cw
                    arc 118.61178240159508 78.419105297175160 88.645319635617880 42.340516325827230 ccw
                    """),
                Arguments.of("pocket 1702", """
                    contour
                    move 75.790763442119260 44.624539177257375
                    arc 45.157062041598735 41.851779585891140 70.266489075836990 24.085842198293720 cw
                    line 55.163758133154360 23.079205936636060
                    line 43.578774847987950 36.745893448634746
                    line 44.810633464576696 57.104652947993564
                    line 70.562268272008950 65.849574371087240
                    arc 37.663562215670250 46.488929626455910 75.790763442119260 44.624539177257375 cw
                    """));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("outlines")
    void isRecognisedWithItsInscribedCircleAsLargestHole(String name, String text) throws Exception {
        Contour outline = ContourFile.read(new StringReader(text), name).get(0);
        PocketProfile profile = PocketProfile.fromContours(List.of(outline));
        Recognition.Result r = Recognition.of(profile);
        double inradius = RegionOffsetter.inradius(List.of(outline.ccw()), TOL);
        assertEquals(2 * inradius, r.maxHoleDiameterMm(), 20 * profile.compar(), name);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("outlines")
    void itsPassesClearTheFloorWithinTheOutline(String name, String text) throws Exception {
        Contour outline = ContourFile.read(new StringReader(text), name).get(0);
        PocketTechnology t = new PocketTechnology(6, 0.6, 0.1, 0, -3, 3, 3000, 300, 100);
        PocketPlan plan = PassPlanner.plan(Recognition.of(PocketProfile.fromContours(List.of(outline))), t, false);
        Toolpath path = PocketToolpath.of(plan, true);
        Geometry swept = PocketCoverageTest.swept(path, -3, 3);
        Geometry wall = RegionPocketTest.polygon(outline);
        double uncut =
                wall.buffer(-3, 64).buffer(3 - 0.01, 64).difference(swept).getArea();
        double outside = swept.difference(wall.buffer(0.01, 64)).getArea();
        System.out.printf(Locale.ROOT, "%s: uncut %.5f mm2, outside %.5f mm2%n", name, uncut, outside);
        assertTrue(outside < 1e-3, name + ": beyond the outline " + outside + " mm2");
        assertTrue(uncut < 1e-3, name + ": uncut " + uncut + " mm2");
    }

    /** The same generator, 2000 outlines: every one recognised. */
    @Test
    void twoThousandRandomOutlinesAreAllRecognised() throws Exception {
        Random rnd = new Random(7);
        StringBuilder refused = new StringBuilder();
        int count = 0;
        for (int k = 0; k < 2000; k++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketCleanUpTest.tech(rnd);
            try {
                Recognition.of(PocketProfile.fromContours(List.of(p.get(0).ccw().reversed())));
            } catch (CamInputException e) {
                count++;
                refused.append("\n  pocket ").append(k).append(": ").append(e.getMessage());
            }
        }
        assertEquals(0, count, "refused:" + refused);
    }
}
