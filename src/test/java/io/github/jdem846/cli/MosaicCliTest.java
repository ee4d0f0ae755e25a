package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.DemTiles;
import io.github.jdem846.testing.MiniJson;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The commands take several files, a directory or a quoted glob as one grid: {@code render a b c d} draws what
 * {@code render whole} draws, byte for byte; {@code info} describes the mosaic and lists its files; an empty
 * directory, a pattern that matches nothing, tiles that do not fit and an output over a tile are refused.
 */
class MosaicCliTest {

    private static final Path WHOLE = Path.of("testdata", "dem", "jacksboro_srtm3s_wgs84.tif");
    private static final String[] LOW_SUN = {"--shadows", "sweep", "--sun-azimuth", "135", "--sun-elevation", "6",
        "--threads", "2", "-q"};

    @TempDir
    static Path tmp;

    private static Path dir;
    private static List<Path> tiles;

    @BeforeAll
    static void cut() throws IOException {
        Dem whole = DemReader.read(WHOLE);
        dir = Files.createDirectories(tmp.resolve("tiles"));
        tiles = DemTiles.geoTiff(whole, DemTiles.quarters(403, 344, 200, 170, 1), dir, "j", 4326, true);
        Files.writeString(dir.resolve("README.txt"), "four tiles of Jacksboro");
    }

    private static byte[] render(String out, String... inputs) throws IOException {
        List<String> args = new ArrayList<>(List.of("render"));
        args.addAll(List.of(inputs));
        args.addAll(List.of("-o", tmp.resolve(out).toString()));
        args.addAll(List.of(LOW_SUN));
        CliRun run = CliRun.of(args.toArray(new String[0]));
        assertEquals(0, run.exitCode(), run.err());
        return Files.readAllBytes(tmp.resolve(out));
    }

    @Test
    void severalFilesADirectoryAndAGlobRenderAsTheWholeDem() throws IOException {
        byte[] whole = render("whole.png", WHOLE.toString());
        List<String> names = tiles.stream().map(Path::toString).toList();
        assertArrayEquals(whole, render("files.png", names.toArray(new String[0])), "four files");
        assertArrayEquals(whole, render("dir.png", dir.toString()), "a directory");
        assertArrayEquals(whole, render("glob.png", dir + "/j_*.tif"), "a glob the shell did not expand");
        CliRun run = CliRun.of("shadows", dir.toString(), "-o", tmp.resolve("s.png").toString(), "--sun-azimuth",
                "135", "--sun-elevation", "6");
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.err().contains("note: " + dir + ": 4 DEM files (1 other entry skipped)"), run.err());
    }

    @Test
    void infoDescribesTheMosaicAndListsItsFiles() {
        CliRun run = CliRun.of("info", dir.toString());
        assertEquals(0, run.exitCode(), run.err());
        String out = run.out();
        assertTrue(out.contains("Format:         mosaic of 4 files read as one grid"), out);
        for (Path t : tiles) {
            assertTrue(out.contains(t.toString()), t + " in " + out);
        }
        assertTrue(out.contains("Size:           403 × 344 cells"), out);
        assertTrue(out.contains("Extent:         west -84.41375, east -84.0779166667, south 36.44625, north"
                + " 36.7329166667°"), out);
        assertTrue(out.contains("CRS:            WGS 84 (EPSG:4326), geographic"), out);
        assertTrue(out.contains("the files overlap"), out);

        CliRun json = CliRun.of("info", "--json", tiles.get(0).toString(), tiles.get(1).toString());
        assertEquals(0, json.exitCode(), json.err());
        @SuppressWarnings("unchecked")
        Map<String, Object> j = (Map<String, Object>) MiniJson.parse(json.out());
        assertEquals("mosaic", j.get("format"));
        assertEquals(List.of(tiles.get(0).toString(), tiles.get(1).toString()), j.get("files"));
        assertEquals(403.0, ((Number) j.get("width")).doubleValue());
        assertEquals(171.0, ((Number) j.get("height")).doubleValue());
    }

    @Test
    void oneFileIsStillDescribedAsItself() {
        CliRun run = CliRun.of("info", WHOLE.toString());
        assertEquals(0, run.exitCode(), run.err());
        assertTrue(run.out().startsWith("File:           " + WHOLE + "\nFormat:         GeoTIFF\n"), run.out());
        assertFalse(run.out().contains("Files:"), run.out());
    }

    @Test
    void anEmptyDirectoryOrAGlobWithoutMatchIsRefused() throws IOException {
        Path empty = Files.createDirectories(tmp.resolve("empty"));
        CliRun a = CliRun.of("render", empty.toString(), "-o", tmp.resolve("e.png").toString());
        assertEquals(1, a.exitCode(), a.err());
        assertTrue(a.err().strip().startsWith("jdem846: " + empty + ": is a directory with no DEM file in it"),
                a.err());
        CliRun b = CliRun.of("render", dir + "/*.hgt", "-o", tmp.resolve("g.png").toString());
        assertEquals(2, b.exitCode(), b.err());
        assertTrue(b.err().contains("no DEM file matches '" + dir + "/*.hgt'"), b.err());
        assertFalse(Files.exists(tmp.resolve("e.png")) || Files.exists(tmp.resolve("g.png")));
    }

    @Test
    void tilesThatDoNotFitAreRefusedNamingBoth() {
        CliRun run = CliRun.of("render", tiles.get(0).toString(), "testdata/dem/bigtujunga_srtm30m_utm11n.tif", "-o",
                tmp.resolve("x.png").toString());
        assertEquals(1, run.exitCode(), run.err());
        String err = run.err().strip();
        assertTrue(err.startsWith("jdem846: testdata/dem/bigtujunga_srtm30m_utm11n.tif: has 'WGS 84 / UTM zone 11N'"
                + " (EPSG:32611), projected, but " + tiles.get(0) + " has 'WGS 84' (EPSG:4326), geographic"), err);
        assertEquals(1, err.lines().count(), err);
        assertFalse(Files.exists(tmp.resolve("x.png")));
    }

    @Test
    void anOutputOverATileIsRefused() throws IOException {
        byte[] before = Files.readAllBytes(tiles.get(2));
        CliRun run = CliRun.of("render", dir.toString(), "-o", tiles.get(2).toString());
        assertEquals(2, run.exitCode(), run.err());
        assertTrue(run.err().contains(tiles.get(2).getFileName().toString()), run.err());
        assertArrayEquals(before, Files.readAllBytes(tiles.get(2)));
    }
}
