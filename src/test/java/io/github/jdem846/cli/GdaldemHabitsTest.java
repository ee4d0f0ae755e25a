package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.testing.DemTiles;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * What gdaldem users type: {@code hillshade IN OUT} and {@code tint IN COLORFILE OUT} beside {@code -o}, gdaldem's
 * short options as aliases, {@code -combined}/{@code -igor} with gdaldem's bytes, the note when the bundled sample
 * is drawn, option texts that name only options of their command, and the completion script.
 */
class GdaldemHabitsTest {

    private static final String LUX = "testdata/dem/luxembourg_srtm30s_wgs84.tif";
    private static final String JB = "testdata/dem/jacksboro_srtm3s_wgs84.tif";
    private static final String COLORS = "testdata/golden/tint/colors/table2_percent.txt";
    private static final Path GOLDEN = Path.of("testdata", "golden", "hillshade");

    @TempDir
    Path dir;

    /** Runs the arguments, asserts {@code expected} as the exit status and returns the run. */
    private static CliRun run(int expected, String... args) {
        CliRun run = CliRun.of(args);
        assertEquals(expected, run.exitCode(), String.join(" ", args) + "\n" + run.err());
        return run;
    }

    /** Runs a command that writes {@code out}, asserts success and returns the file's bytes. */
    private static byte[] written(Path out, String... args) throws IOException {
        run(0, args);
        return Files.readAllBytes(out);
    }

    private String out(String name) {
        return dir.resolve(name).toString();
    }

    @Test
    void hillshadeInOutWritesWhatMinusOWrites() throws IOException {
        byte[] withO = written(dir.resolve("o.png"), "hillshade", LUX, "-o", out("o.png"), "-q", "--method", "horn");
        byte[] positional = written(dir.resolve("p.png"), "hillshade", LUX, out("p.png"), "-q", "--method", "horn");
        assertArrayEquals(withO, positional);
        byte[] tifWithO = written(dir.resolve("o.tif"), "hillshade", "-q", LUX, "-o", out("o.tif"));
        assertArrayEquals(tifWithO, written(dir.resolve("p.tif"), "hillshade", "-q", LUX, out("p.tif")), "GeoTIFF");
    }

    @Test
    void severalInputsBeforeThePositionalOutputAreOneMosaic() throws IOException {
        Path tilesDir = Files.createDirectories(dir.resolve("tiles"));
        List<Path> tiles = DemTiles.geoTiff(DemReader.read(Path.of(JB)), DemTiles.quarters(403, 344, 200, 170, 1),
                tilesDir, "j", 4326, true);
        List<String> args = new ArrayList<>(List.of("hillshade", "-q"));
        tiles.forEach(t -> args.add(t.toString()));
        List<String> positional = new ArrayList<>(args);
        positional.add(out("p.png"));
        List<String> withO = new ArrayList<>(args);
        withO.addAll(List.of("-o", out("o.png")));
        byte[] whole = written(dir.resolve("w.png"), "hillshade", "-q", JB, "-o", out("w.png"));
        assertArrayEquals(whole, written(dir.resolve("o.png"), withO.toArray(new String[0])), "-o");
        assertArrayEquals(whole, written(dir.resolve("p.png"), positional.toArray(new String[0])), "positional");
        assertArrayEquals(whole, written(dir.resolve("d.png"), "hillshade", "-q", tilesDir.toString(),
                out("d.png")), "a directory, then the output");
    }

    @Test
    void tintInColorfileOutWritesWhatTintAndMinusOWrite() throws IOException {
        byte[] withO = written(dir.resolve("o.png"), "tint", LUX, "--tint", COLORS, "-o", out("o.png"), "-q");
        assertArrayEquals(withO, written(dir.resolve("p.png"), "tint", LUX, COLORS, out("p.png"), "-q"));
        byte[] nearest = written(dir.resolve("n.png"), "tint", LUX, "--tint", COLORS, "--nearest-color", "-o",
                out("n.png"), "-q");
        assertFalse(java.util.Arrays.equals(withO, nearest), "the mode must matter for this test");
        assertArrayEquals(nearest, written(dir.resolve("g.png"), "tint", "-q", "-nearest_color_entry", "-alpha",
                LUX, COLORS, out("g.png")), "gdaldem's spelling of the flags");
        byte[] named = written(dir.resolve("e.png"), "tint", LUX, "--tint", "etopo1", "-o", out("e.png"), "-q");
        assertArrayEquals(named, written(dir.resolve("f.png"), "tint", LUX, "etopo1", out("f.png"), "-q"),
                "a built-in ramp in the colour file's place");
    }

    @Test
    void withMinusOEveryFileIsAnInput() throws IOException {
        // the last FILE is the output only without -o: here both files are inputs, one grid (the same cells twice,
        // averaged), and the copy is read, not written
        Path copy = Files.copy(Path.of(LUX), dir.resolve("lux.tif"));
        byte[] before = Files.readAllBytes(copy);
        byte[] one = written(dir.resolve("one.png"), "hillshade", "-q", LUX, "-o", out("one.png"));
        CliRun run = run(0, "hillshade", "-q", LUX, copy.toString(), "-o", out("two.png"));
        assertTrue(run.err().contains("note: the files overlap"), run.err());
        assertArrayEquals(one, Files.readAllBytes(dir.resolve("two.png")));
        assertArrayEquals(before, Files.readAllBytes(copy));
    }

    @Test
    void missingOrAmbiguousPositionalFormsAreBadUsage() throws IOException {
        Path dem = Files.copy(Path.of(LUX), dir.resolve("dem.tif"));
        byte[] before = Files.readAllBytes(dem);
        assertUsage(List.of("hillshade", LUX), "without -o, hillshade takes IN... OUT", "1 FILE", "-o OUT");
        assertUsage(List.of("hillshade"), "missing the output", "-o OUT", "hillshade IN OUT");
        assertUsage(List.of("hillshade", LUX, dem.toString()), "'" + dem + "' is an existing DEM file",
                "overwritten", "-o OUT");
        assertUsage(List.of("hillshade", LUX, dir.toString()), "is a directory");
        assertUsage(List.of("hillshade", LUX, dir + "/*.png"), "is a glob pattern");
        assertUsage(List.of("tint", LUX, out("t.png")), "without -o, tint takes IN... COLORFILE OUT",
                "colour file", "2 FILEs");
        assertUsage(List.of("tint", LUX, dem.toString(), out("t.png")), "'" + dem + "' is in the colour file's place",
                "--tint");
        assertUsage(List.of("tint", LUX, COLORS, out("t.png"), "--tint", "gray"), "two colour ramps");
        assertUsage(List.of("hillshade", LUX, out("h.png"), "-igor", "-combined"), "--combined and --igor");
        assertUsage(List.of("hillshade", LUX, out("h.png"), "-igor", "--method", "horn"), "--method horn and --igor");
        assertArrayEquals(before, Files.readAllBytes(dem), "the DEM named as an output is left alone");
        try (var files = Files.list(dir)) {
            assertEquals(List.of(dem), files.toList(), "nothing written");
        }
    }

    private static void assertUsage(List<String> args, String... expected) {
        CliRun run = run(2, args.toArray(new String[0]));
        String first = run.err().lines().findFirst().orElse("");
        for (String e : expected) {
            assertTrue(first.contains(e), "'" + e + "' in: " + run.err());
        }
        assertTrue(run.err().contains("Try 'jdem846 " + args.get(0) + " --help'."), run.err());
    }

    @Test
    void gdaldemShortOptionsMeanTheLongOnes() throws IOException {
        byte[] longNames = written(dir.resolve("l.png"), "hillshade", "-q", LUX, "-o", out("l.png"), "--method",
                "horn", "--sun-azimuth", "100", "--sun-elevation", "20", "--z-factor", "3", "--xy-scale", "111120");
        byte[] shortNames = written(dir.resolve("s.png"), "hillshade", "-q", LUX, out("s.png"), "--method", "horn",
                "-az", "100", "-alt", "20", "-z", "3", "-s", "111120", "-compute_edges");
        assertArrayEquals(longNames, shortNames);
        byte[] noEdgesFlag = written(dir.resolve("e.png"), "hillshade", "-q", LUX, out("e.png"), "--method", "horn",
                "-az", "100", "-alt", "20", "-z", "3", "-s", "111120");
        assertArrayEquals(shortNames, noEdgesFlag, "-compute_edges changes nothing: edges are always computed");
        for (String method : new String[] {"multidirectional", "combined", "igor"}) {
            byte[] flag = written(dir.resolve(method + "-flag.png"), "hillshade", "-q", LUX,
                    out(method + "-flag.png"), "-" + method);
            byte[] option = written(dir.resolve(method + ".png"), "hillshade", "-q", LUX, "-o",
                    out(method + ".png"), "--method", method);
            assertArrayEquals(option, flag, "-" + method);
            assertFalse(java.util.Arrays.equals(option, noEdgesFlag), method + " differs from horn");
        }
        byte[] render = written(dir.resolve("r.png"), "render", "-q", LUX, "-o", out("r.png"), "-az", "100",
                "-alt", "20");
        assertArrayEquals(render, written(dir.resolve("r2.png"), "render", "-q", LUX, "-o", out("r2.png"),
                "--sun-azimuth", "100", "--sun-elevation", "20"), "render shares the sun options");
    }

    @Test
    void combinedAndIgorGiveGdaldemsBytes() throws IOException {
        // testdata/golden/hillshade/README.md: gdaldem hillshade -compute_edges -s 111120 -igor (Luxembourg) and
        // -s 111120 -combined -az 57 -alt 5 -z 5
        run(0, "hillshade", "-q", LUX, out("igor.png"), "-igor", "-s", "111120", "-az", "315", "-compute_edges");
        assertSameGray(GOLDEN.resolve("lux_igor_s111120_az315.png"), dir.resolve("igor.png"));
        run(0, "hillshade", "-q", LUX, out("comb.png"), "-combined", "-s", "111120", "-az", "57", "-alt", "5", "-z",
                "5");
        assertSameGray(GOLDEN.resolve("lux_combined_s111120_az57_alt5_z5.png"), dir.resolve("comb.png"));
    }

    @Test
    void igorSaysTheSunElevationIsNotUsed() {
        CliRun run = run(0, "hillshade", "-q", LUX, out("i.png"), "-igor", "-alt", "30");
        assertTrue(run.err().contains("note: igor uses only the sun's azimuth; --sun-elevation has no effect"),
                run.err());
        assertFalse(run(0, "hillshade", "-q", LUX, out("j.png"), "-igor").err().contains("igor uses"));
    }

    @Test
    void theBundledSampleIsAnnouncedOnStderr() {
        for (String command : new String[] {"render", "hillshade", "tint", "shadows"}) {
            CliRun sample = run(0, command, "-q", "-o", out(command + ".png"), "--width", "60");
            assertEquals(1, sample.err().lines().filter(l -> l.equals("jdem846: note: " + InputOptions.SAMPLE_NOTE))
                    .count(), sample.err());
            assertTrue(InputOptions.SAMPLE_NOTE.contains("Big Tujunga"));
            CliRun file = run(0, command, "-q", LUX, "-o", out(command + "-lux.png"));
            assertFalse(file.err().contains("bundled sample"), file.err());
        }
    }

    /** Every {@code --option} a command's help mentions is an option of that command. */
    @Test
    void helpTextsNameOnlyTheirOwnOptions() {
        CommandLine main = Main.commandLine();
        Pattern option = Pattern.compile("(?<![\\w-])--[a-z][a-z_-]*[a-z]");
        for (CommandLine sub : main.getSubcommands().values()) {
            String help = sub.getUsageMessage();
            Matcher m = option.matcher(help);
            while (m.find()) {
                assertTrue(sub.getCommandSpec().findOption(m.group()) != null, "'" + sub.getCommandName()
                        + " --help' mentions " + m.group() + ", which it does not have");
            }
        }
        assertFalse(main.getSubcommands().get("render").getUsageMessage().contains("--algorithm"));
    }

    @Test
    void hillshadeAndTintShowMinusOAsOptionalInItsPlace() {
        for (String command : new String[] {"hillshade", "tint"}) {
            String help = run(0, command, "--help").out();
            String synopsis = help.substring(0, help.indexOf("\n      [FILE...]"));
            assertTrue(synopsis.contains("[-o=OUT]"), synopsis);
            String list = help.substring(synopsis.length());
            assertTrue(list.indexOf("--scale=") < list.indexOf("--output=")
                    && list.indexOf("--output=") < list.indexOf("--world-file"), "-o listed as render lists it:\n"
                    + list);
            assertTrue(list.replaceAll("\\s+", " ").contains(command.equals("tint") ? "IN... COLORFILE OUT"
                    : "IN... OUT"), list);
        }
        assertTrue(run(0, "render", "--help").out().replaceAll("\\s+", " ").contains(" -o=OUT "),
                "render still needs -o");
        assertTrue(run(2, "render", LUX).err().contains("Missing required option: '--output=OUT'"));
    }

    @Test
    void completionWritesAScriptForEveryCommand() {
        CliRun run = run(0, "completion");
        String script = run.out();
        assertTrue(script.contains("complete -F"), script.substring(0, Math.min(500, script.length())));
        for (String word : new String[] {"hillshade", "tint", "render", "tiles", "-compute_edges", "-igor", "-az",
            "--sun-elevation"}) {
            assertTrue(script.contains(word), word);
        }
        assertTrue(run(0, "--help").out().contains("completion"), "listed in jdem846 --help");
    }

    private static void assertSameGray(Path golden, Path ours) throws IOException {
        BufferedImage g = ImageIO.read(golden.toFile());
        BufferedImage o = ImageIO.read(ours.toFile());
        assertEquals(g.getWidth(), o.getWidth());
        assertEquals(g.getHeight(), o.getHeight());
        int equal = 0;
        for (int y = 0; y < g.getHeight(); y++) {
            for (int x = 0; x < g.getWidth(); x++) {
                int a = g.getRaster().getSample(x, y, 0);
                int b = o.getRaster().getSample(x, y, 0);
                assertTrue(Math.abs(a - b) <= 1, "pixel " + x + "," + y + ": gdaldem " + a + ", ours " + b);
                equal += a == b ? 1 : 0;
            }
        }
        assertTrue(equal >= 0.999 * g.getWidth() * g.getHeight(), equal + " equal pixels");
    }
}
