package io.github.jdem846.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** CRS resolution through Apache SIS: EPSG codes, ESRI WKT, units and ellipsoids. */
class CrsResolverTest {

    /** An ESRI .prj of NAD83 / California zone 3 in US survey feet (as ArcGIS writes it). */
    static final String CA3_FTUS_WKT = "PROJCS[\"NAD_1983_StatePlane_California_III_FIPS_0403_Feet\","
            + "GEOGCS[\"GCS_North_American_1983\",DATUM[\"D_North_American_1983\",SPHEROID[\"GRS_1980\",6378137.0,"
            + "298.257222101]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\",0.0174532925199433]],"
            + "PROJECTION[\"Lambert_Conformal_Conic\"],PARAMETER[\"False_Easting\",6561666.666666666],"
            + "PARAMETER[\"False_Northing\",1640416.666666667],PARAMETER[\"Central_Meridian\",-120.5],"
            + "PARAMETER[\"Standard_Parallel_1\",37.06666666666667],PARAMETER[\"Standard_Parallel_2\",38.43333333333333],"
            + "PARAMETER[\"Latitude_Of_Origin\",36.5],UNIT[\"Foot_US\",0.3048006096012192]]";

    @TempDir
    Path tmp;

    @Test
    void utm11nIsProjectedInMetresOnWgs84() {
        CrsInfo crs = CrsResolver.fromEpsg(32611).orElseThrow();
        assertEquals(CrsInfo.Kind.PROJECTED, crs.kind());
        assertEquals(1.0, crs.linearUnitMeters());
        assertEquals(32611, crs.epsg());
        assertTrue(crs.name().contains("UTM zone 11N"), crs.name());
        assertEquals(6378137.0, crs.ellipsoid().semiMajorAxis());
        assertEquals(298.257223563, crs.ellipsoid().inverseFlattening(), 1e-9);
        assertNotNull(crs.sisCrs());
    }

    @Test
    void epsg4326IsGeographicWithEastNorthAxes() {
        CrsInfo crs = CrsResolver.fromEpsg(4326).orElseThrow();
        assertEquals(CrsInfo.Kind.GEOGRAPHIC, crs.kind());
        // EPSG's own order is latitude first; the kept CRS is normalised to x = east.
        assertEquals("east", crs.sisCrs().getCoordinateSystem().getAxis(0).getDirection().name().toLowerCase());
    }

    @Test
    void codesOutsideSisOfflineSubsetAreEmptyNotFatal() {
        assertTrue(CrsResolver.fromEpsg(2193).isEmpty(), "NZTM2000 needs the full EPSG database");
        assertTrue(CrsResolver.fromEpsg(32767).isEmpty(), "user-defined");
        assertTrue(CrsResolver.fromEpsg(0).isEmpty());
    }

    @Test
    void nztmPrjParses() throws IOException {
        String wkt = Files.readString(Path.of("testdata/dem/maungawhau-volcano_10m_nztm-approx.prj"));
        CrsInfo crs = CrsResolver.fromWkt(wkt);
        assertEquals(CrsInfo.Kind.PROJECTED, crs.kind());
        assertEquals(1.0, crs.linearUnitMeters());
        assertEquals(6378137.0, crs.ellipsoid().semiMajorAxis());
        assertEquals(298.257222101, crs.ellipsoid().inverseFlattening(), 1e-9, "GRS 1980");
    }

    @Test
    void usSurveyFootWktGives1200Over3937Metres() {
        CrsInfo crs = CrsResolver.fromWkt(CA3_FTUS_WKT);
        assertEquals(CrsInfo.Kind.PROJECTED, crs.kind());
        assertEquals(1200.0 / 3937.0, crs.linearUnitMeters(), 1e-15);
        assertEquals(1200.0 / 3937.0, CrsResolver.linearUnitMetres(9003), 1e-15);
        assertEquals(0.3048, CrsResolver.linearUnitMetres(9002), 1e-15);
        assertEquals(1.0, CrsResolver.linearUnitMetres(9001));
        assertTrue(Double.isNaN(CrsResolver.linearUnitMetres(9102)), "a degree is not a length");
    }

    @Test
    void gridFloatWithAFeetPrjHasCellsOf1200Over3937MetresPerFoot() throws IOException {
        Files.write(tmp.resolve("ft.flt"), ByteBuffer.allocate(3 * 2 * 4).array());
        Files.writeString(tmp.resolve("ft.hdr"), "ncols 3\nnrows 2\nxllcorner 6561666\nyllcorner 1640416\n"
                + "cellsize 100\nNODATA_value -9999\nbyteorder LSBFIRST\n");
        Files.writeString(tmp.resolve("ft.prj"), CA3_FTUS_WKT);
        GridGeometry g = DemReader.read(tmp.resolve("ft.flt")).geometry();
        assertEquals(100 * 1200.0 / 3937.0, g.cellWidthMeters(0), 1e-12);
        assertEquals(100 * 1200.0 / 3937.0, g.cellHeightMeters(1), 1e-12);
        assertTrue(g.hasMetricUnits());
        assertFalse(g.crs().assumed());
        // The false origin (6561666.67 ftUS E, 1640416.67 ftUS N) is at 36.5°N, 120.5°W.
        LatLon origin = GeoLocator.forCrs(g.crs()).orElseThrow().toLatLon(6561666.666666666, 1640416.666666667);
        assertEquals(36.5, origin.latitude(), 1e-9);
        assertEquals(-120.5, origin.longitude(), 1e-9);
    }

    @Test
    void garbledWktIsRefusedWithAMessage() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> CrsResolver.fromWkt("PROJCS[\"broken\", GEOGCS["));
        assertTrue(e.getMessage().contains("WKT"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> CrsResolver.fromWkt(" "));
    }

    @Test
    void ellipsoidAndDatumCodesKnownOffline() {
        assertEquals(298.257222101, CrsResolver.ellipsoidFromEpsg(7019).orElseThrow().inverseFlattening(), 1e-9);
        assertEquals(6378206.4, CrsResolver.ellipsoidFromEpsg(7008).orElseThrow().semiMajorAxis(), 1e-6,
                "Clarke 1866");
        assertEquals(6378137.0, CrsResolver.ellipsoidOfDatumEpsg(6326).orElseThrow().semiMajorAxis());
        assertTrue(CrsResolver.ellipsoidFromEpsg(1).isEmpty());
    }
}
