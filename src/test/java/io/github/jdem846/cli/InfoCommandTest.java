package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.testing.MiniJson;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * {@code jdem846 info}: the JSON object's keys and values, checked against testdata/PROVENANCE.md, GDAL
 * ({@code gdalinfo -json}) and hand calculation; the text form; help and version.
 */
class InfoCommandTest {

    @SuppressWarnings("unchecked")
    private static Map<String, Object> json(String... args) {
        CliRun run = CliRun.of(args);
        assertEquals(0, run.exitCode(), run.err());
        assertEquals("", run.err());
        return (Map<String, Object>) MiniJson.parse(run.out().strip());
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> map(Object o) {
        return (Map<String, Object>) o;
    }

    private static double num(Object o) {
        return (Double) o;
    }

    @Test
    void jsonHasEveryRequiredKey() {
        Map<String, Object> j = json("info", "--json", "testdata/dem/bigtujunga_srtm30m_utm11n.tif");
        for (String key : List.of("format", "width", "height", "dataType", "crs", "epsg", "nodata", "nodataCount",
                "min", "max", "cellSize", "cellSizeMeters", "extentLatLon")) {
            assertTrue(j.containsKey(key), "missing key " + key + " in " + j);
        }
    }

    @Test
    void projectedGeoTiff() {
        Map<String, Object> j = json("info", "--json", "testdata/dem/bigtujunga_srtm30m_utm11n.tif");
        assertEquals("GeoTIFF", j.get("format"));
        assertEquals(1197.0, j.get("width"));
        assertEquals(643.0, j.get("height"));
        assertEquals("Int16", j.get("dataType"));
        assertEquals(32611.0, j.get("epsg"));
        assertTrue(((String) j.get("crs")).contains("UTM zone 11N"));
        assertEquals(32767.0, j.get("nodata"), "GDAL_NODATA 32767, never used");
        assertEquals(0.0, j.get("nodataCount"));
        assertEquals(315.0, j.get("min"));
        assertEquals(2295.0, j.get("max"));
        assertEquals(30.0, map(j.get("cellSize")).get("x"));
        assertEquals(30.0, num(map(j.get("cellSizeMeters")).get("x")), 1e-12);
        assertEquals(30.0, num(map(j.get("cellSizeMeters")).get("y")), 1e-12);
        // gdalinfo -json → wgs84Extent: west −118.3457332, east −117.953114, south 34.2313881, north 34.4089801
        Map<String, Object> ll = map(j.get("extentLatLon"));
        assertEquals(-118.3457332, num(ll.get("west")), 1e-7);
        assertEquals(-117.953114, num(ll.get("east")), 1e-7);
        assertEquals(34.2313881, num(ll.get("south")), 1e-7);
        assertEquals(34.4089801, num(ll.get("north")), 1e-7);
        Map<String, Object> ext = map(j.get("extent"));
        assertEquals(376313.6554542635, num(ext.get("west")), 1e-9, "PROVENANCE corner 376313.655");
        assertEquals(3807917.8276283755, num(ext.get("north")), 1e-9);
    }

    @Test
    void geographicGridFloatWithNoData() {
        Map<String, Object> j = json("info", "--json", "testdata/dem/luxembourg_srtm30s_wgs84.flt");
        assertEquals("ESRI GridFloat", j.get("format"));
        assertEquals("Float32", j.get("dataType"));
        assertEquals(-9999.0, j.get("nodata"));
        assertEquals(3942.0, j.get("nodataCount"));
        assertEquals(141.0, j.get("min"));
        assertEquals(547.0, j.get("max"));
        assertEquals(Boolean.FALSE, j.get("crsAssumed"));
        Map<String, Object> m = map(j.get("cellSizeMeters"));
        // Centre row 45 is centred at 49.441667 + 44.5 × 30″ = 49.8125°N. PROJ 9.1.1 geod (GeographicLib):
        // echo "49.8125 6 49.8125 6.008333333333333337" | geod +ellps=WGS84 -I -f %.12f -F %.6f → 599.785025 m;
        // echo "49.816666666666666 6 49.80833333333333 6" | geod ... → 926.878736 m.
        assertEquals(599.785025, num(m.get("x")), 2e-6);
        assertEquals(926.878736, num(m.get("y")), 2e-6);
        Map<String, Object> ll = map(j.get("extentLatLon"));
        assertEquals(5.741666666666666, num(ll.get("west")), 1e-12);
        assertEquals(50.19166666666666, num(ll.get("north")), 1e-12);
    }

    @Test
    void nanNoDataIsTheStringNaNAndUnknownProjectionGivesNullLatLon() {
        Map<String, Object> j = json("info", "--json",
                "testdata/variants/luxembourg_n01_float32_nan-nodata_deflate_pred3_tile32.tif");
        assertEquals("NaN", j.get("nodata"));
        assertEquals(3942.0, j.get("nodataCount"));
        Map<String, Object> v = json("info", "--json", "testdata/dem/maungawhau-volcano_10m_nztm-approx.tif");
        assertNull(v.get("extentLatLon"), "EPSG:2193 cannot be resolved offline");
        assertEquals(2193.0, v.get("epsg"));
        assertEquals(10.0, num(map(v.get("cellSizeMeters")).get("x")), 1e-12, "metre from ProjLinearUnitsGeoKey");
        assertNull(v.get("nodata"), "no GDAL_NODATA tag");
        assertFalse(((List<?>) v.get("notices")).isEmpty());
    }

    @Test
    void noFileDescribesTheBundledSample() {
        Map<String, Object> j = json("info", "--json");
        assertEquals(600.0, j.get("width"));
        assertEquals(400.0, j.get("height"));
        assertEquals(614.0, j.get("min"));
        assertEquals(2095.0, j.get("max"));
        assertTrue(((String) j.get("file")).contains("sample"));
    }

    @Test
    void unknownUnitsGiveNullMetricSize(@org.junit.jupiter.api.io.TempDir java.nio.file.Path tmp)
            throws java.io.IOException {
        java.nio.file.Files.write(tmp.resolve("u.flt"), new byte[4 * 4]);
        java.nio.file.Files.writeString(tmp.resolve("u.hdr"),
                "ncols 2\nnrows 2\nxllcorner 500000\nyllcorner 4000000\ncellsize 30\nbyteorder LSBFIRST\n");
        Map<String, Object> j = json("info", "--json", tmp.resolve("u.flt").toString());
        assertNull(j.get("cellSizeMeters"));
        assertNull(j.get("crs"));
        assertNull(j.get("epsg"));
        assertNull(j.get("nodata"), "no NODATA_value means no no-data, not 0");
        assertEquals(0.0, j.get("nodataCount"), "zeros are elevations");
        assertEquals(0.0, j.get("min"));
    }

    @Test
    void textNamesEverything() {
        CliRun run = CliRun.of("info", "testdata/dem/jacksboro_srtm3s_wgs84.tif");
        assertEquals(0, run.exitCode(), run.err());
        for (String s : List.of("GeoTIFF", "403 × 344", "Int16", "EPSG:4326", "min 236, max 1076", "Extent lat/lon",
                "m at the centre row", "none declared")) {
            assertTrue(run.out().contains(s), "missing '" + s + "' in\n" + run.out());
        }
    }

    @Test
    void helpAndVersion() {
        CliRun help = CliRun.of("info", "--help");
        assertEquals(0, help.exitCode());
        assertTrue(help.out().contains("--json"), help.out());
        CliRun version = CliRun.of("info", "--version");
        assertEquals(0, version.exitCode());
        assertTrue(version.out().startsWith("jdem846"), version.out());
    }

    @Test
    void jsonEscapesStrings() {
        assertEquals("\"a\\\"b\\\\c\\nd\\u0001\"", Json.quote("a\"b\\c\nd\u0001"));
        assertEquals("null", Json.number(Double.NaN));
        assertEquals("-3", Json.number(-3.0));
        assertEquals("0.5", Json.number(0.5));
    }

    @Test
    void numbersArePlainExceptFloat32Sentinels() {
        assertEquals("-9999", InfoReport.fmt(-9999));
        assertEquals("0.00833333333333", InfoReport.fmt(1 / 120.0));
        assertEquals("376313.655454", InfoReport.fmt(376313.655454263499));
        // GDAL_NODATA -3.4028234663852886e+38 (float32's lowest value), as ESRI tools write it
        assertEquals("-3.40282346639E+38", InfoReport.fmt(-3.4028234663852886e+38));
    }
}
