package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

class WorldFileTest {

    @Test
    void coefficientsMatchAHandComputation() {
        // A 300 × 200 unit area shown as 3 × 4 pixels: pixels are 100 wide and 50 high; the first pixel's centre
        // is half a pixel east and south of the north-west corner (1000, 2000).
        GeoReference geo = new GeoReference(1000, 2000, 1300, 1800, CrsInfo.UNKNOWN);
        WorldFile wf = WorldFile.of(geo, 3, 4);
        assertEquals(new WorldFile(100, 0, 0, -50, 1050, 1975), wf);
        assertEquals("100.0\n0.0\n0.0\n-50.0\n1050.0\n1975.0\n", wf.toText());
    }

    @Test
    void fullSizeImageOfARealDemUsesTheDemCellsCentres() {
        // bigtujunga .hdr: xllcorner 376313.6554542635, yllcorner 3788627.8276283755, cellsize 30, 1197 × 643
        GridGeometry g = TestDems.load(TestDems.BIG_TUJUNGA).geometry();
        WorldFile wf = WorldFile.of(GeoReference.of(g), 1197, 643);
        assertEquals(30, wf.a(), 1e-9);
        assertEquals(-30, wf.e(), 1e-9);
        assertEquals(376313.6554542635 + 15, wf.c(), 1e-6);
        assertEquals(3788627.8276283755 + 643 * 30 - 15, wf.f(), 1e-6);
    }

    @Test
    void lastPixelCentreIsHalfAPixelInsideTheSouthEastCorner() {
        GeoReference geo = new GeoReference(-84.41375, 36.73291666666667, -84.07791666666667, 36.44625,
                CrsInfo.geographic("WGS 84", 4326, null));
        for (int[] size : new int[][]{{1, 1}, {1, 57}, {57, 1}, {403, 344}, {1000, 7}}) {
            WorldFile wf = WorldFile.of(geo, size[0], size[1]);
            double lastX = wf.a() * (size[0] - 1) + wf.c();
            double lastY = wf.e() * (size[1] - 1) + wf.f();
            assertEquals(geo.eastX() - wf.a() / 2, lastX, 1e-12);
            assertEquals(geo.southY() - wf.e() / 2, lastY, 1e-12);
        }
    }

    @ParameterizedTest(name = "{0} as {1}×{2}")
    @CsvSource({
            "bigtujunga_srtm30m_utm11n, 1197, 643",
            "bigtujunga_srtm30m_utm11n, 598, 321",
            "bigtujunga_srtm30m_utm11n, 1, 1",
            "jacksboro_srtm3s_wgs84, 403, 344",
            "jacksboro_srtm3s_wgs84, 201, 172",
            "jacksboro_srtm3s_wgs84, 1000, 7"})
    void agreesWithGdal(String dataset, int width, int height) throws IOException {
        Path golden = Path.of("testdata/golden/output", dataset + "_" + width + "x" + height + ".wld");
        List<String> gdal = Files.readAllLines(golden).stream().map(String::strip).filter(s -> !s.isEmpty())
                .toList();
        WorldFile wf = WorldFile.of(GeoReference.of(TestDems.load(dataset).geometry()), width, height);
        double[] ours = {wf.a(), wf.d(), wf.b(), wf.e(), wf.c(), wf.f()};
        assertEquals(6, gdal.size());
        for (int i = 0; i < 6; i++) {
            double expected = Double.parseDouble(gdal.get(i));
            // GDAL prints 10 decimals.
            assertEquals(expected, ours[i], 1e-9 + Math.abs(expected) * 1e-15, "line " + (i + 1));
        }
    }

    @Test
    void textReadsBackAsTheSameNumbersWithoutExponents() {
        WorldFile wf = new WorldFile(8.333333333333334E-4, 0, -0.0, -8.333333333333334E-4, -84.41333333333333,
                1.0E-7);
        String[] lines = wf.toText().split("\n");
        double[] expected = {wf.a(), wf.d(), wf.b(), wf.e(), wf.c(), wf.f()};
        assertEquals(6, lines.length);
        for (int i = 0; i < 6; i++) {
            assertEquals(false, lines[i].contains("E") || lines[i].contains("e"), lines[i]);
            assertEquals(expected[i], Double.parseDouble(lines[i]), 0.0, lines[i]);
        }
    }
}
