package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

class SunCommandTest {

    private record Run(int exit, String out, String err) {
    }

    private static Run run(String... args) {
        CommandLine cl = Main.commandLine();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int exit = cl.execute(args);
        return new Run(exit, out.toString(), err.toString());
    }

    private static final Pattern JSON_OBJECT = Pattern.compile(
            "\\{(\"[A-Za-z]+\":(\"[^\"]*\"|-?\\d+(\\.\\d+)?|true|false|null),)*"
                    + "\"[A-Za-z]+\":(\"[^\"]*\"|-?\\d+(\\.\\d+)?|true|false|null)}\\R?");

    private static double number(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":(-?\\d+(\\.\\d+)?)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return Double.parseDouble(m.group(1));
    }

    private static String string(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":(\"([^\"]*)\"|null)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return m.group(2);
    }

    @Test
    void spaExampleAsText() {
        Run r = run("sun", "--time", "2003-10-17T12:30:30-07:00", "--at", "39.742476,-105.1786", "--height",
                "1830.14", "--pressure", "820", "--temperature", "11", "--delta-t", "67");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().contains("194.3402"), r.out());
        assertTrue(r.out().contains("50.1116"), r.out());
        assertTrue(r.out().contains("sunrise    2003-10-17T06:12:4"), r.out());
    }

    @Test
    void spaExampleAsJson() {
        Run r = run("sun", "--time", "2003-10-17T12:30:30-07:00", "--at", "39.742476,-105.1786", "--height",
                "1830.14", "--pressure", "820", "--temperature", "11", "--delta-t", "67", "--json");
        assertEquals(0, r.exit(), r.err());
        assertTrue(JSON_OBJECT.matcher(r.out()).matches(), r.out());
        assertEquals(194.34024, number(r.out(), "azimuth"), 1e-3);
        assertEquals(50.11162, number(r.out(), "zenith"), 1e-3);
        assertEquals(39.88838, number(r.out(), "elevation"), 1e-3);
        assertTrue(string(r.out(), "sunrise").startsWith("2003-10-17T06:12:4"));
        assertTrue(string(r.out(), "sunset").endsWith("-07:00"));
        assertTrue(string(r.out(), "transit").startsWith("2003-10-17T11:46:0"));
        assertEquals("regular", string(r.out(), "day"));
        assertEquals(67, number(r.out(), "deltaT"), 1e-9);
    }

    @Test
    void zoneIdIsKeptInTheOutput() {
        Run r = run("sun", "--time", "2024-06-21T05:00[Europe/Luxembourg]", "--at", "49.6116,6.1319", "--json");
        assertEquals(0, r.exit(), r.err());
        String sunrise = string(r.out(), "sunrise");
        assertTrue(sunrise.startsWith("2024-06-21T05:2") && sunrise.endsWith("+02:00[Europe/Luxembourg]"), sunrise);
        assertTrue(r.out().contains("\"belowHorizon\":true"), "05:00 is before sunrise: " + r.out());
        assertTrue(r.out().contains("\"deltaTEstimated\":true"));
    }

    @Test
    void polarNightHasNullSunriseAndSaysWhy() {
        Run r = run("sun", "--time", "2024-12-21T12:00+01:00", "--at", "78.22,15.65", "--json");
        assertEquals(0, r.exit(), r.err());
        assertTrue(JSON_OBJECT.matcher(r.out()).matches(), r.out());
        assertEquals(null, string(r.out(), "sunrise"));
        assertEquals(null, string(r.out(), "sunset"));
        assertEquals("polar_night", string(r.out(), "day"));
        assertTrue(number(r.out(), "elevation") < 0);
        Run text = run("sun", "--time", "2024-06-21T00:00+02:00", "--at", "78.22,15.65");
        assertTrue(text.out().contains("none (polar day"), text.out());
    }

    @Test
    void negativeLatitudeWithoutEquals() {
        Run r = run("sun", "--time", "2024-06-21T12:00Z", "--at", "-33.92,18.42");
        assertEquals(0, r.exit(), r.err());
        assertTrue(r.out().contains("33.920000 S"), r.out());
    }

    @Test
    void badPlacesAndTimesAreUsageErrors() {
        Run lat = run("sun", "--time", "2024-06-21T12:00Z", "--at", "91,0");
        assertEquals(2, lat.exit());
        assertTrue(lat.err().contains("latitude must be between -90 and 90"), lat.err());
        Run lon = run("sun", "--time", "2024-06-21T12:00Z", "--at", "0,-200");
        assertEquals(2, lon.exit());
        assertTrue(lon.err().contains("longitude"), lon.err());
        Run junk = run("sun", "--time", "2024-06-21T12:00Z", "--at", "here");
        assertEquals(2, junk.exit());
        assertTrue(junk.err().contains("LAT,LON"), junk.err());
        Run noZone = run("sun", "--time", "2024-06-21T12:00", "--at", "0,0");
        assertEquals(2, noZone.exit());
        assertTrue(noZone.err().contains("has no UTC offset or zone") && noZone.err().contains("add one"),
                noZone.err());
    }

    @Test
    void otherBodiesAreRefusedForSunByDate() {
        Run moon = run("sun", "--time", "2024-06-21T12:00Z", "--at", "0,0", "--body", "moon");
        assertEquals(2, moon.exit());
        assertTrue(moon.err().contains("Earth only") && moon.err().contains("Moon"), moon.err());
        Run radius = run("sun", "--time", "2024-06-21T12:00Z", "--at", "0,0", "--radius", "1000000");
        assertEquals(2, radius.exit());
        assertTrue(radius.err().contains("Earth only"), radius.err());
        Run both = run("sun", "--time", "2024-06-21T12:00Z", "--at", "0,0", "--body", "earth", "--radius", "1");
        assertEquals(2, both.exit());
        assertEquals(0, run("sun", "--time", "2024-06-21T12:00Z", "--at", "0,0", "--body", "EARTH").exit());
    }

    @Test
    void farYearNeedsDeltaT() {
        Run r = run("sun", "--time", "3500-06-21T12:00Z", "--at", "0,0");
        assertEquals(1, r.exit());
        assertTrue(r.err().contains("delta T"), r.err());
        assertEquals(0, run("sun", "--time", "3500-06-21T12:00Z", "--at", "0,0", "--delta-t", "8000").exit());
    }
}
