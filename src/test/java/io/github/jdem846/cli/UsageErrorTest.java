package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Bad usage exits with status 2 and says so in one line naming the option, the value and what is allowed, plus at
 * most a hint line to --help; never the usage text, never an exception's name, and no output file. Values that can
 * only be judged against the grid (a window outside it, a size too large or too small for it) too, once its header
 * is read and before any cell is. A picture too large for memory is rendered in tiles; one whose smallest tile cannot
 * fit is refused at once (exit 1).
 */
class UsageErrorTest {

    private static final String BT = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";
    private static final String TIME = "2024-06-21T12:00Z";

    @TempDir
    Path dir;

    private static Arguments bad(String command, String args, String... mentions) {
        return Arguments.of(command, Arrays.asList(args.split(" ")), List.of(mentions));
    }

    static Stream<Arguments> usageErrors() {
        return Stream.of(
                // parse errors
                bad("render", "--no-such-option", "--no-such-option"),
                bad("render", "--width", "--width"),
                bad("render", "--width abc", "--width", "abc"),
                bad("hillshade", "--z-factor lots", "--z-factor", "lots"),
                bad("shadows", "--threads 1.5", "--threads", "1.5"),
                // output size, known without the grid
                bad("render", "--width 0", "--width", "got 0", "1 to 100000"),
                bad("render", "--height 0", "--height", "got 0", "1 to 100000"),
                bad("render", "--width -3", "--width", "got -3", "1 to 100000"),
                bad("render", "--width 2000000000", "--width", "got 2000000000", "1 to 100000"),
                bad("render", "--width 100000 --height 100000", "'--width' and '--height'", "10000000000",
                        "at most 2147483639"),
                bad("render", "--width 100 --scale 2", "--scale", "--width/--height", "not both"),
                bad("render", "--scale NaN", "--scale", "got NaN", "above 0 and at most 100000"),
                bad("render", "--scale -1", "--scale", "got -1.0", "above 0 and at most 100000"),
                bad("render", "--scale 0", "--scale", "got 0.0", "above 0 and at most 100000"),
                bad("render", "--scale Infinity", "--scale", "got Infinity", "above 0 and at most 100000"),
                bad("tint", "--scale 1e6", "--scale", "got 1000000.0", "above 0 and at most 100000"),
                // output size against the grid's 1197 × 643 cells
                bad("render", "--width 100000", "--width", "100000×53718", "1197×643",
                        "at most 100000 pixels per side and 2147483639 in all"),
                bad("hillshade", "--height 100000", "--height", "1197×643", "2147483639 in all"),
                bad("render", "--scale 1e-9", "--scale", "1.0E-9", "1197×643", "smallest scale", "0.000778"),
                bad("shadows", "--scale 90", "--scale", "107730×57870", "at most 100000 pixels per side"),
                // execution
                bad("render", "--threads 0", "--threads", "got 0", "1 to 1024"),
                bad("render", "--threads 100000", "--threads", "got 100000", "1 to 1024"),
                bad("tint", "--threads -2", "--threads", "got -2", "1 to 1024"),
                bad("render", "--tile-size 0", "--tile-size", "got 0", "16 to 4096"),
                bad("hillshade", "--tile-size -5", "--tile-size", "got -5", "16 to 4096"),
                bad("render", "--tile-size 2000000000", "--tile-size", "got 2000000000", "16 to 4096"),
                bad("render", "--memory 0", "--memory", "'0'", "512m or 4g", "above 0"),
                bad("hillshade", "--memory lots", "--memory", "'lots'", "512m or 4g"),
                bad("shadows", "--memory -5m", "--memory", "'-5m'", "above 0"),
                bad("tint", "--memory 9999999999t", "--memory", "'9999999999t'", "below 8 EiB"),
                // hillshade knobs
                bad("render", "--z-factor 1e308", "--z-factor", "got 1.0E308", "> 0 and ≤ 1000000"),
                bad("render", "--z-factor NaN", "--z-factor", "got NaN", "> 0 and ≤ 1000000"),
                bad("hillshade", "--z-factor Infinity", "--z-factor", "got Infinity", "> 0 and ≤ 1000000"),
                bad("hillshade", "--z-factor 0", "--z-factor", "got 0.0", "> 0 and ≤ 1000000"),
                bad("render", "--z-factor -2", "--z-factor", "got -2.0", "> 0 and ≤ 1000000"),
                bad("render", "--light-multiple NaN", "--light-multiple", "got NaN", "between 0 and 1000000"),
                bad("render", "--light-intensity 5", "--light-intensity", "got 5.0", "between 0 and 1"),
                bad("hillshade", "--dark-intensity NaN", "--dark-intensity", "got NaN", "between 0 and 1"),
                bad("render", "--spot-exponent 0", "--spot-exponent", "got 0.0", "between 0.01 and 128"),
                bad("hillshade", "--xy-scale 0", "--xy-scale", "got 0.0", "positive number"),
                bad("hillshade", "--xy-scale NaN", "--xy-scale", "got NaN", "finite number above 0"),
                bad("render", "--xy-scale Infinity", "--xy-scale", "got Infinity", "positive number"),
                // windows
                bad("render", "--window 1,2,3", "--window", "'1,2,3'", "WEST,SOUTH,EAST,NORTH"),
                bad("render", "--window cells:a,0,1,1", "--window", "'cells:a,0,1,1'", "cells:COL,ROW,WIDTH,HEIGHT"),
                bad("render", "--window cells:-1,0,10,10", "--window", "(-1, 0)", "col, row ≥ 0"),
                bad("tint", "--window cells:0,0,0,10", "--window", "0×10", "width, height ≥ 1"),
                bad("render", "--window 3,4,1,2", "--window", "west 3.0", "west < east and south < north"),
                bad("render", "--window NaN,0,1,1", "--window", "west NaN", "finite"),
                bad("render", "--window cells:1190,0,100,10", "--window", "100×10 cells at column 1190",
                        "inside the 1197×643 grid"),
                bad("hillshade", "--window 0,0,1,1", "--window", "west 0.0", "does not intersect",
                        "extent west 376313.6554542635", "north 3807917.8276283755"),
                bad("shadows", "--window -9e5,-9e5,-8e5,-8e5", "--window", "west -900000.0", "does not intersect"),
                // names
                bad("render", "--shadows foo", "--shadows", "'foo'", "march, sweep, exact, none"),
                bad("shadows", "--algorithm foo", "--algorithm", "'foo'", "march, sweep, exact"),
                bad("shadows", "--algorithm none", "--algorithm", "none", "sweep, march or exact"),
                bad("render", "--hillshade foo", "--hillshade", "'foo'", "jdem846", "horn", "multidirectional",
                        "none"),
                bad("hillshade", "--method foo", "--method", "'foo'", "jdem846", "horn", "multidirectional"),
                bad("render", "--tint foo", "--tint", "'foo'", "hypsometric", "etopo1"),
                bad("tint", "--tint rainbow", "--tint", "'rainbow'", "hypsometric"),
                bad("tint", "--tint gray --exact-color", "--exact-color", "colour files"),
                bad("render", "--exact-color --nearest-color", "--exact-color", "--nearest-color", "not both"),
                // the sun
                bad("render", "--sun-elevation 95", "--sun-elevation", "got 95.0", "between -90 and 90"),
                bad("shadows", "--sun-elevation -91", "--sun-elevation", "got -91.0", "between -90 and 90"),
                bad("render", "--sun-elevation NaN", "--sun-elevation", "got NaN", "between -90 and 90"),
                bad("hillshade", "--sun-elevation Infinity", "--sun-elevation", "got Infinity",
                        "between -90 and 90"),
                bad("render", "--sun-azimuth NaN", "--sun-azimuth", "got NaN", "finite number"),
                bad("shadows", "--sun-azimuth -Infinity", "--sun-azimuth", "got -Infinity", "finite number"),
                bad("render", "--sun-time garbage", "--sun-time", "'garbage'", "ISO-8601"),
                bad("render", "--sun-time " + TIME + " --sun-at 95,0", "--sun-at", "got 95.0", "between -90 and 90"),
                bad("shadows", "--sun-time " + TIME + " --sun-at 0,500", "--sun-at", "got 500.0",
                        "between -180 and 180"),
                bad("render", "--sun-time " + TIME + " --sun-at NaN,0", "--sun-at", "'NaN'", "LAT,LON"),
                bad("render", "--sun-at 1,1", "--sun-at", "need --sun-time"),
                bad("hillshade", "--twilight", "--twilight", "need --sun-time"),
                bad("render", "--sun-time " + TIME + " --sun-elevation 4", "--sun-time", "--sun-elevation",
                        "not both"),
                // shadows and the body
                bad("render", "--shadow-intensity 2", "--shadow-intensity", "got 2.0", "between 0 and 1"),
                bad("render", "--shadow-intensity NaN", "--shadow-intensity", "got NaN", "between 0 and 1"),
                bad("render", "--shadow-intensity -0.1", "--shadow-intensity", "got -0.1", "between 0 and 1"),
                bad("shadows", "--refraction NaN", "--refraction", "got NaN", "between -1 and 1"),
                bad("render", "--curvature --refraction 2", "--refraction", "got 2.0", "between -1 and 1"),
                bad("render", "--radius -1", "--radius", "got -1.0", "positive number of metres"),
                bad("shadows", "--radius NaN", "--radius", "got NaN", "positive number of metres"),
                bad("render", "--radius Infinity", "--radius", "got Infinity", "positive number of metres"),
                bad("render", "--body pluto", "--body", "'pluto'", "earth, moon or mars"),
                bad("render", "--body moon --radius 5", "--body", "--radius", "not both"),
                bad("shadows", "--body mars --sun-time " + TIME, "--body", "Earth only"),
                // info and sun
                bad("info", "--sun-at 1,1", "--sun-at", "needs --sun-time"),
                bad("info", "--sun-time 2024-13-01T00:00Z", "--sun-time", "'2024-13-01T00:00Z'"),
                bad("info", "--radius 0", "--radius", "got 0.0", "positive number of metres"),
                bad("sun", "--height 30000", "--height", "got 30000.0", "between -500 and 20000"),
                bad("sun", "--pressure 0", "--pressure", "got 0.0", "above 0 and at most 2000"),
                bad("sun", "--temperature NaN", "--temperature", "got NaN", "between -100 and 100"),
                bad("sun", "--delta-t 1e9", "--delta-t", "got 1.0E9", "±200000"),
                bad("sun", "--at 91,0", "--at", "between -90 and 90"));
    }

    /**
     * Each case finishes in well under a second: a size refused against the grid must be refused before anything
     * is allocated (before the fix, {@code --width 100000} ran for 48 s and needed 5.7 GB).
     */
    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("usageErrors")
    @Timeout(value = 10, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void badUsageIsOneLineNamingTheOptionAndWhatIsAllowed(String command, List<String> args,
                                                         List<String> mentions) {
        Path out = dir.resolve("out.png");
        List<String> all = new ArrayList<>(List.of(command));
        switch (command) {
            case "info" -> all.add(BT);
            case "sun" -> all.addAll(List.of("--time", TIME, "--at", "34.3,-118.2"));
            default -> all.addAll(List.of(BT, "-o", out.toString(), "-q"));
        }
        all.addAll(args);
        String what = String.join(" ", all);
        CliRun run = CliRun.of(all.toArray(String[]::new));
        String err = run.err();
        assertEquals(2, run.exitCode(), what + ": " + err);
        assertFalse(err.contains("Exception"), what + ": no exception's name: " + err);
        assertFalse(err.contains("Usage:"), what + ": no usage text: " + err);
        List<String> lines = err.lines().toList();
        assertTrue(lines.size() >= 1 && lines.size() < 3, what + ": one line and a hint: " + err);
        assertTrue(lines.get(0).startsWith("jdem846: "), what + ": " + err);
        for (String m : mentions) {
            assertTrue(lines.get(0).contains(m), what + ": the message mentions '" + m + "': " + err);
        }
        if (lines.size() == 2) {
            assertTrue(lines.get(1).endsWith("'jdem846 " + command + " --help'."), what + ": the hint: " + err);
        }
        assertEquals("", run.out(), what);
        assertFalse(Files.exists(out), what + ": no output file");
    }

    /** The ends of the ranges are allowed: the limits are not off by one. */
    @Test
    void theEndsOfTheRangesAreAllowed() throws IOException {
        Path out = dir.resolve("edge.png");
        String[][] cases = {
            {"render", "--width", "16", "--threads", "1024", "--tile-size", "16", "--z-factor", "1000000",
                "--shadows", "sweep", "--shadow-intensity", "1", "--sun-azimuth", "-1e6", "--sun-elevation", "90"},
            {"hillshade", "--scale", "0.000778", "--tile-size", "4096", "--sun-elevation", "-90",
                "--light-intensity", "0", "--dark-intensity", "1", "--spot-exponent", "128"},
            {"tint", "--window", "cells:1196,642,1,1", "--threads", "1"},
            {"shadows", "--window", "cells:0,0,1197,643", "--curvature", "--refraction", "-1", "--radius",
                "6371000"}};
        for (String[] c : cases) {
            String[] args = Stream.concat(Stream.of(c[0], BT, "-o", out.toString(), "-q"),
                    Arrays.stream(c, 1, c.length)).toArray(String[]::new);
            CliRun run = CliRun.of(args);
            assertEquals(0, run.exitCode(), String.join(" ", args) + ": " + run.err());
            assertTrue(Files.exists(out));
            Files.delete(out);
        }
    }

    /** Below the horizon is allowed and casts shadow over every cell. */
    @Test
    void aSunBelowTheHorizonShadowsEveryCell() throws IOException {
        Path out = dir.resolve("night.png");
        CliRun run = CliRun.of("shadows", BT, "-o", out.toString(), "-q", "--width", "60", "--sun-elevation", "-10");
        assertEquals(0, run.exitCode(), run.err());
        Raster r = ImageIO.read(out.toFile()).getRaster();
        for (int y = 0; y < r.getHeight(); y++) {
            for (int x = 0; x < r.getWidth(); x++) {
                assertEquals(255, r.getSample(x, y, 0), "in shadow at " + x + "," + y);
            }
        }
    }

    /**
     * A picture larger than the memory budget is rendered in tiles; one whose smallest tile, with the halo its cast
     * shadows need toward a sun 2° high, cannot fit the budget is refused at once, before any cell is read, with
     * one line giving what it needs and what to do (exit 1: the command is right, the machine or budget too small).
     */
    @Test
    void aPictureWhoseSmallestTileCannotFitIsRefusedBeforeItIsMade() {
        Path png = dir.resolve("low.png");
        CliRun run = CliRun.of("render", BT, "-q", "--shadows", "sweep", "--sun-elevation", "2", "--memory", "256k",
                "-o", png.toString());
        String output = run.err().strip();
        assertEquals(1, run.exitCode(), output);
        assertEquals(1, output.lines().count(), output);
        assertTrue(output.startsWith("jdem846: even the smallest tile, 16×16 pixels, with the halo read around it")
                && output.contains("more than the memory budget of 256 KiB") && output.contains("--memory"),
                output);
        assertFalse(output.contains("Exception") || output.contains("out of memory"), "refused up front: " + output);
        assertFalse(Files.exists(png), "no picture written");
    }
}
