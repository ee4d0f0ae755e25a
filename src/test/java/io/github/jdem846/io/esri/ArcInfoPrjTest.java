package io.github.jdem846.io.esri;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The old ArcInfo projection file of USGS NED GridFloat tiles. Expected datums, ellipsoids, EPSG codes and units
 * are what GDAL 3.6.2's {@code gdalsrsinfo} makes of the same files (OGRSpatialReference::importFromESRI); real
 * grids with such a file must read like the same grids with their WKT {@code .prj}.
 */
class ArcInfoPrjTest {

    /** The .prj of a USGS NED 1/3 arc-second GridFloat tile, as The National Map delivered them. */
    private static final String NED = "Projection    GEOGRAPHIC\nDatum         NAD83\nZunits        METERS\n"
            + "Units         DD\nSpheroid      GRS1980\nXshift        0.0000000000\nYshift        0.0000000000\n"
            + "Parameters    \n";

    @TempDir
    Path tmp;

    private static CrsInfo parse(String text, List<String> notices) {
        assertTrue(ArcInfoPrj.looksLikeOne(text), text);
        return ArcInfoPrj.parse(text, "t.prj", notices);
    }

    private static String prj(String projection, String datum, String spheroid, String units, String more) {
        return "Projection " + projection + "\nDatum " + datum + "\nSpheroid " + spheroid + "\nUnits " + units
                + "\n" + more + "Parameters\n";
    }

    /** Copies a testdata GridFloat into tmp with the given .prj text. */
    private Path gridFloatWith(String dataset, String prjText) throws IOException {
        Path flt = tmp.resolve("g.flt");
        Files.copy(TestDems.DEM_DIR.resolve(dataset + ".flt"), flt);
        Files.copy(TestDems.DEM_DIR.resolve(dataset + ".hdr"), tmp.resolve("g.hdr"));
        Files.writeString(tmp.resolve("g.prj"), prjText);
        return flt;
    }

    @Test
    void nedTileIsGeographicNad83AndMeasuresLikeItsWktTwin() throws IOException {
        List<String> notices = new ArrayList<>();
        CrsInfo crs = parse(NED, notices);
        assertEquals(CrsInfo.Kind.GEOGRAPHIC, crs.kind());
        assertEquals(4269, crs.epsg());
        assertEquals(Ellipsoid.GRS80, crs.ellipsoid());
        assertTrue(notices.get(0).contains("NAD83 (EPSG:4269)"), notices.toString());

        DemInfo ned = DemReader.inspect(gridFloatWith(TestDems.LUXEMBOURG, NED));
        GridGeometry wkt = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.LUXEMBOURG + ".flt")).geometry();
        GridGeometry g = ned.geometry();
        for (int row : new int[] {0, 45, 89}) {
            // GRS 1980 and WGS 84 differ in the 10th digit of the flattening
            assertEquals(wkt.cellWidthMeters(row), g.cellWidthMeters(row), 1e-6, "row " + row);
            assertEquals(wkt.cellHeightMeters(row), g.cellHeightMeters(row), 1e-6, "row " + row);
        }
        assertEquals(wkt.latLonExtent(), g.latLonExtent());
        assertTrue(ned.notices().stream().anyMatch(n -> n.contains("ArcInfo projection file")), ned.notices()
                .toString());
    }

    @Test
    void utmZonesByDatumAndHemisphere() throws IOException {
        List<String> notices = new ArrayList<>();
        CrsInfo wgs84 = parse(prj("UTM", "WGS84", "WGS84", "METERS", "Zone 11\nYshift 0.0\n"), notices);
        assertEquals(32611, wgs84.epsg());
        assertEquals(1.0, wgs84.linearUnitMeters());
        assertEquals(32733, parse(prj("UTM", "WGS84", "WGS84", "METERS", "Zone 33\nYshift 10000000\n"),
                notices).epsg());
        assertEquals(32611, parse(prj("UTM", "WGS84", "WGS84", "METERS", "Zone 11\nYshift none\n"), notices)
                .epsg(), "GDAL reads a Yshift that is not a number as 0: north");
        assertEquals(26913, parse(prj("UTM", "NAD83", "GRS1980", "METERS", "Zone 13\n"), notices).epsg());
        CrsInfo nad27 = parse(prj("UTM", "NAD27", "CLARKE1866", "METERS", "Zone 13\n"), notices);
        assertEquals(26713, nad27.epsg());
        assertEquals(6378206.4, nad27.ellipsoid().semiMajorAxis());
        assertEquals(294.978698213898, nad27.ellipsoid().inverseFlattening());

        // Big Tujunga's GridFloat with the same CRS in this format reads exactly like it with its WKT .prj
        GridGeometry arcInfo = DemReader.inspect(gridFloatWith(TestDems.BIG_TUJUNGA,
                prj("UTM", "WGS84", "WGS84", "METERS", "Zone 11\nYshift 0.0\n"))).geometry();
        GridGeometry wkt = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ".flt")).geometry();
        assertEquals(wkt.cellWidthMeters(100), arcInfo.cellWidthMeters(100));
        assertEquals(wkt.latLonExtent().orElseThrow().north(), arcInfo.latLonExtent().orElseThrow().north(),
                1e-9);
    }

    @Test
    void linearUnitsAsGdalReadsThem() {
        List<String> notices = new ArrayList<>();
        CrsInfo feet = parse(prj("UTM", "NAD83", "GRS1980", "FEET", "Zone 13\n"), notices);
        assertEquals(0.304800609601219, feet.linearUnitMeters(), 1e-15);
        assertNull(feet.epsg(), "EPSG:26913 is in metres");
        CrsInfo perMetre = parse(prj("ALBERS", "NAD83", "GRS1980", "3.280839895", ""), notices);
        assertEquals(0.3048, perMetre.linearUnitMeters(), 1e-11);
        assertEquals(CrsInfo.Kind.PROJECTED, perMetre.kind());
        assertTrue(notices.get(notices.size() - 1).contains("latitude/longitude are unavailable"), notices
                .toString());
        assertEquals(1.0, parse(prj("LAMBERT", "NAD83", "GRS1980", "METERS", ""), notices).linearUnitMeters());
    }

    @Test
    void datumThenSpheroidThenSemiAxesThenWgs84() {
        List<String> notices = new ArrayList<>();
        CrsInfo clarke = parse(prj("GEOGRAPHIC", "XYZ", "CLARKE1866", "DD", ""), notices);
        assertEquals(4008, clarke.epsg());
        assertEquals(294.978698213898, clarke.ellipsoid().inverseFlattening());
        CrsInfo axes = ArcInfoPrj.parse("Projection GEOGRAPHIC\nDatum XYZ\nSpheroid ABC\n"
                + "Parameters 6378388.0 6356911.946\n", "t.prj", notices);
        assertEquals(6378388.0, axes.ellipsoid().semiMajorAxis());
        assertEquals(297.0, axes.ellipsoid().inverseFlattening(), 1e-3);
        notices.clear();
        CrsInfo fallback = parse(prj("GEOGRAPHIC", "XYZ", "ABC", "DD", ""), notices);
        assertEquals(4326, fallback.epsg());
        assertTrue(notices.get(0).contains("WGS 84 assumed"), notices.toString());
    }

    @Test
    void elevationsInFeetAskForAZFactor() {
        List<String> notices = new ArrayList<>();
        parse(NED.replace("Zunits        METERS", "Zunits        FEET"), notices);
        assertTrue(notices.stream().anyMatch(n -> n.contains("--z-factor 0.3048")), notices.toString());
    }

    @Test
    void aBadZoneLeavesTheCrsUnknownWithTheReason() throws IOException {
        DemInfo info = DemReader.inspect(gridFloatWith(TestDems.LUXEMBOURG,
                prj("UTM", "WGS84", "WGS84", "METERS", "Zone 99\n")));
        assertEquals(CrsInfo.Kind.UNKNOWN, info.geometry().crs().kind());
        assertTrue(info.notices().stream().anyMatch(n -> n.contains("g.prj could not be parsed")
                && n.contains("UTM Zone is '99'")), info.notices().toString());
        assertThrows(IllegalArgumentException.class, () -> ArcInfoPrj.parse("Projection\n", "t.prj",
                new ArrayList<>()));
    }
}
