package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.job.Sun;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.ZoomRange;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import picocli.CommandLine;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code jdem846 tiles} end to end on Luxembourg (30″, no-data outside the border, so some tiles hold nothing): the
 * tiles and the summary, the archive, and the exit status of bad usage (2) and of outputs that cannot be written (1);
 * and the job a program gets from parsed arguments ({@link TilesCommand#tileJob}) without running it.
 */
class TilesCommandTest {

    private static final String LUX = "testdata/dem/luxembourg_srtm30s_wgs84.tif";

    @TempDir
    Path dir;

    @Test
    void writesTheTilesAndSaysHowMany() throws IOException {
        Path out = dir.resolve("lux");
        CliRun run = CliRun.of("tiles", LUX, "--zoom", "9-10", "-o", out.toString(), "--png-level", "1");
        assertEquals(0, run.exitCode(), run.err());
        long files;
        try (Stream<Path> s = Files.walk(out)) {
            files = s.filter(p -> p.toString().endsWith(".png")).count();
        }
        // zoom 9: 4 tiles; zoom 10: 12 overlap the box, and one corner holds only no-data
        assertEquals(15, files);
        assertTrue(run.out().contains("wrote 15 tiles"), run.out());
        assertTrue(run.out().contains("1 tiles without data left out"), run.out());
        assertTrue(run.out().contains("zoom 10: 11 tiles written of 12"), run.out());

        Path archive = dir.resolve("lux.pmtiles");
        CliRun pm = CliRun.of("tiles", LUX, "--zoom", "9", "-o", archive.toString(), "-q", "--shadows", "sweep");
        assertEquals(0, pm.exitCode(), pm.err());
        assertEquals("", pm.out());
        byte[] head = Files.readAllBytes(archive);
        assertEquals("PMTiles", new String(head, 0, 7, java.nio.charset.StandardCharsets.US_ASCII));
    }

    @Test
    void aMosaicDirectoryMakesTheTilesOfTheWholeDem() throws IOException {
        Path whole = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.flt");
        io.github.jdem846.raster.Dem dem = io.github.jdem846.io.DemReader.read(whole);
        Path tiles = Files.createDirectories(dir.resolve("quarters"));
        io.github.jdem846.testing.DemTiles.gridFloat(dem,
                io.github.jdem846.testing.DemTiles.quarters(dem.width(), dem.height(), dem.width() / 2,
                        dem.height() / 2, 1),
                tiles, "jb", Path.of("testdata/dem/jacksboro_srtm3s_wgs84.prj"));
        Path fromWhole = dir.resolve("whole");
        Path fromTiles = dir.resolve("fromtiles");
        CliRun a = CliRun.of("tiles", whole.toString(), "--zoom", "10-11", "-o", fromWhole.toString(), "-q",
                "--shadows", "sweep", "--sun-elevation", "6");
        assertEquals(0, a.exitCode(), a.err());
        CliRun b = CliRun.of("tiles", tiles.toString(), "--zoom", "10-11", "-o", fromTiles.toString(), "-q",
                "--shadows", "sweep", "--sun-elevation", "6");
        assertEquals(0, b.exitCode(), b.err());
        assertTrue(b.err().contains("4 DEM files"), b.err());
        java.util.List<Path> pngs;
        try (Stream<Path> s = Files.walk(fromWhole)) {
            pngs = s.filter(p -> p.toString().endsWith(".png")).map(fromWhole::relativize).sorted().toList();
        }
        try (Stream<Path> s = Files.walk(fromTiles)) {
            assertEquals(pngs, s.filter(p -> p.toString().endsWith(".png")).map(fromTiles::relativize).sorted()
                    .toList(), "the same tiles");
        }
        assertTrue(pngs.size() > 4, "tiles at two zooms: " + pngs);
        for (Path png : pngs) {
            org.junit.jupiter.api.Assertions.assertArrayEquals(Files.readAllBytes(fromWhole.resolve(png)),
                    Files.readAllBytes(fromTiles.resolve(png)), png + " of the four quarters is that of the DEM");
        }
    }

    @Test
    void badUsageIsExitStatusTwo() {
        String out = dir.resolve("t").toString();
        String[][] bad = {
            {"tiles", LUX, "-o", out},
            {"tiles", LUX, "--zoom", "12-3", "-o", out},
            {"tiles", LUX, "--zoom", "0-23", "-o", out},
            {"tiles", LUX, "--zoom", "3", "-o", dir.resolve("t.mbtiles").toString()},
            {"tiles", LUX, "--zoom", "3", "-o", out, "--xy-scale", "111120"},
            {"tiles", LUX, "--zoom", "3", "-o", out, "--sun-time", "2024-06-21T12:00Z", "--sun-per-tile"},
            {"tiles", LUX, "--zoom", "3", "-o", out, "--png-level", "10"},
        };
        for (String[] args : bad) {
            CliRun run = CliRun.of(args);
            assertEquals(2, run.exitCode(), String.join(" ", args) + ": " + run.err());
            assertTrue(run.err().startsWith("jdem846: "), run.err());
            assertFalse(Files.exists(dir.resolve("t")));
        }
    }

    @Test
    void outputsThatCannotBeWrittenAreExitStatusOne() throws IOException {
        Path full = Files.createDirectories(dir.resolve("full"));
        Files.writeString(full.resolve("mine.txt"), "keep");
        CliRun run = CliRun.of("tiles", LUX, "--zoom", "8", "-o", full.toString());
        assertEquals(1, run.exitCode());
        assertTrue(run.err().contains("not empty"), run.err());
        CliRun missing = CliRun.of("tiles", "no-such-dem.tif", "--zoom", "8", "-o", dir.resolve("m").toString());
        assertEquals(1, missing.exitCode());
        assertTrue(missing.err().contains("no-such-dem.tif"), missing.err());
        try (Stream<Path> left = Files.list(dir)) {
            assertEquals(1, left.count(), "nothing but the directory that was there");
        }
    }

    @Test
    void parsedArgumentsGiveTheTileJobAndTheOutput() throws IOException {
        TilesCommand command = new TilesCommand();
        new CommandLine(command).parseArgs(LUX, "--zoom", "3-5", "--shadows", "sweep", "--sun-elevation", "20",
                "-o", "x.pmtiles");
        StringWriter err = new StringWriter();
        TileJob job = command.tileJob(new PrintWriter(err, true));
        assertEquals(new ZoomRange(3, 5), job.zooms());
        assertEquals(ShadowAlgorithm.SWEEP, job.scene().shadows());
        assertEquals(HillshadeMethod.JDEM846, job.scene().hillshade());
        assertEquals(0.4, job.scene().shadowIntensity());
        assertEquals(Sun.fixed(320, 20), job.sun());
        assertEquals(DemInput.of(Path.of(LUX)), job.input());
        assertEquals(TileJob.DEFAULT_PNG_COMPRESSION, job.pngCompression());
        assertEquals(Path.of("x.pmtiles"), command.output());
        assertEquals("", err.toString(), "nothing to note");
        assertFalse(Files.exists(Path.of("x.pmtiles")), "nothing written");
    }

    @Test
    void theTileJobNotesWhatCallWouldNote() throws IOException {
        Path mosaic = Files.createDirectories(dir.resolve("mosaic"));
        Files.copy(Path.of(LUX), mosaic.resolve("lux.tif"));
        Files.writeString(mosaic.resolve("README.txt"), "not a DEM");
        TilesCommand command = new TilesCommand();
        new CommandLine(command).parseArgs(mosaic.toString(), "--zoom", "8", "--shadows", "march",
                "--thin-features", "--png-level", "1", "-o", dir.resolve("out").toString());
        StringWriter err = new StringWriter();
        TileJob job = command.tileJob(new PrintWriter(err, true));
        assertEquals(DemInput.of(java.util.List.of(mosaic.resolve("lux.tif"))), job.input());
        assertEquals(ShadowAlgorithm.MARCH, job.scene().shadows());
        assertEquals(1, job.pngCompression());
        assertTrue(err.toString().contains("jdem846: note: --thin-features changes only the sweep"), err.toString());
        assertTrue(err.toString().contains("1 DEM file (1 other entry skipped)"), err.toString());
    }

    @Test
    void theTileJobRefusesWhatTheCommandRefuses() {
        String[][] bad = {
            {LUX, "--zoom", "3-5", "-o", "x.pmtiles", "--xy-scale", "2"},
            {LUX, "--zoom", "3-5", "-o", "x.pmtiles", "--sun-time", "2024-06-21T12:00Z", "--sun-per-tile"},
            {LUX, "--zoom", "3-5", "-o", "x.pmtiles", "--sun-at", "49.6,6.1"},
            {LUX, "--zoom", "3-5", "-o", "x.mbtiles"},
            {LUX, "--zoom", "3-5", "-o", "x.pmtiles", "--tint", "no-such-ramp"},
        };
        for (String[] args : bad) {
            TilesCommand command = new TilesCommand();
            CommandLine cl = new CommandLine(command);
            cl.parseArgs(args);
            CommandLine.ParameterException e = assertThrows(CommandLine.ParameterException.class,
                    () -> command.tileJob(new PrintWriter(new StringWriter())), String.join(" ", args));
            assertSame(cl, e.getCommandLine(), "the usage error names the command line that parsed the arguments");
            String[] cli = new String[args.length + 1];
            cli[0] = "tiles";
            System.arraycopy(args, 0, cli, 1, args.length);
            CliRun run = CliRun.of(cli);
            assertEquals(2, run.exitCode(), run.err());
            assertEquals("jdem846: " + e.getMessage(), run.err().lines().findFirst().orElseThrow(),
                    "the same message as jdem846 tiles");
        }
    }
}
