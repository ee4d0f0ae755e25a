package io.github.jdem846.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Path;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.referencing.GeodeticCalculator;
import org.junit.jupiter.api.Test;

/**
 * Metric cell sizes: projected grids from their unit, geographic grids per row on the ellipsoid, checked against
 * geodesic distances from PROJ's {@code geod} (GeographicLib, Karney; values below with the command) and, row by
 * row, from Apache SIS {@link GeodeticCalculator}, whose series are good to about 1e-5 relative at 1″ (it gives
 * 15.5000018 m where PROJ and the closed form N·cos φ·Δλ give 15.5000654 m at 60°N).
 */
class GridGeometryMetricTest {

    private static final double ARC_SECOND = 1.0 / 3600;

    /** Geodesic distance on WGS 84 between two points given as latitude, longitude in degrees. */
    private static double geodesic(double lat1, double lon1, double lat2, double lon2) {
        GeodeticCalculator c = GeodeticCalculator.create(CommonCRS.WGS84.geographic());
        c.setStartGeographicPoint(lat1, lon1);
        c.setEndGeographicPoint(lat2, lon2);
        return c.getGeodesicDistance();
    }

    private static GridGeometry oneArcSecondGrid(double north, int rows) {
        return new GridGeometry(10, rows, 10.0, north, ARC_SECOND, ARC_SECOND,
                CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84), PixelAnchor.CORNER);
    }

    @Test
    void utm30mGridHas30mCells() throws IOException {
        for (String ext : new String[] {".tif", ".flt"}) {
            GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ext)).geometry();
            for (int row : new int[] {0, 321, 642}) {
                assertEquals(30.0, g.cellWidthMeters(row), 1e-12, ext);
                assertEquals(30.0, g.cellHeightMeters(row), 1e-12, ext);
            }
        }
    }

    @Test
    void oneArcSecondAtTheEquator() {
        GridGeometry g = oneArcSecondGrid(ARC_SECOND / 2, 1); // one row centred on the equator
        assertEquals(30.92, g.cellWidthMeters(0), 0.005);
        assertEquals(30.72, g.cellHeightMeters(0), 0.005);
        assertEquals(geodesic(0, 10, 0, 10 + ARC_SECOND), g.cellWidthMeters(0), 1e-5);
        assertEquals(geodesic(ARC_SECOND / 2, 10, -ARC_SECOND / 2, 10), g.cellHeightMeters(0), 1e-5);
    }

    @Test
    void eastWestSizeShrinksRowByRowWithLatitudeAndMatchesGeodesics() {
        // 600 rows of 1″ from 60°N down: every row differs, as a one-constant scale could not.
        GridGeometry g = oneArcSecondGrid(60.0, 600);
        double previous = 0;
        for (int row = 0; row < g.height(); row++) {
            double lat = g.centerY(row);
            double ew = g.cellWidthMeters(row);
            double ns = g.cellHeightMeters(row);
            assertEquals(geodesic(lat, 10, lat, 10 + ARC_SECOND), ew, 1e-5 * ew, "row " + row);
            double north = g.originY() - row * ARC_SECOND;
            assertEquals(geodesic(north, 10, north - ARC_SECOND, 10), ns, 1e-5 * ns, "row " + row);
            assertTrue(ew > previous, "going south (row " + row + ") cells widen");
            previous = ew;
        }
        assertTrue(g.cellWidthMeters(0) < 0.51 * 30.92, "at 60°N a 1″ cell is about half as wide as at the equator");
    }

    @Test
    void rowsNearThePoleStayFiniteAndNonNegative() {
        GridGeometry g = oneArcSecondGrid(90.0, 360); // 89.9°–90°
        for (int row = 0; row < g.height(); row++) {
            double ew = g.cellWidthMeters(row);
            double ns = g.cellHeightMeters(row);
            assertTrue(Double.isFinite(ew) && ew >= 0, "row " + row + " E–W " + ew);
            assertTrue(Double.isFinite(ns) && ns > 0, "row " + row + " N–S " + ns);
            double north = 90.0 - row * ARC_SECOND;
            assertEquals(geodesic(north, 10, north - ARC_SECOND, 10), ns, 1e-5 * ns, "row " + row);
        }
        assertTrue(g.cellWidthMeters(0) < 0.02, "the top row's centre is 0.5″ from the pole");
        assertEquals(geodesic(g.centerY(359), 10, g.centerY(359), 10 + ARC_SECOND), g.cellWidthMeters(359), 1e-5);
    }

    /**
     * One-arc-second cells centred at latitude φ, against PROJ 9.1.1 {@code geod} (Debian proj-bin):
     * E–W: {@code echo "φ 10 φ 10.000277777777777" | geod +ellps=WGS84 -I -f %.12f -F %.9f};
     * N–S: {@code echo "φ+0.5″ 10 φ−0.5″ 10" | geod ...} (third column, metres).
     */
    @Test
    void oneArcSecondCellsMatchProjGeod() {
        double[][] golden = {
            {0, 30.922080776, 30.715076617},
            {30, 26.801744514, 30.792345137},
            {45, 21.901898637, 30.869938171},
            {60 - 0.5 * ARC_SECOND, 15.500065406, 30.947856971},
            {90 - 0.5 * ARC_SECOND, 0.000075209, 31.026105432}};
        for (double[] row : golden) {
            GridGeometry g = oneArcSecondGrid(row[0] + ARC_SECOND / 2, 1);
            assertEquals(row[1], g.cellWidthMeters(0), 2e-9, "E–W at " + row[0]);
            assertEquals(row[2], g.cellHeightMeters(0), 2e-9, "N–S at " + row[0]);
        }
    }

    @Test
    void geographicDatasetsUseTheirEllipsoidPerRow() throws IOException {
        GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.LUXEMBOURG + ".tif")).geometry();
        assertTrue(g.cellWidthMeters(0) < g.cellWidthMeters(g.height() - 1), "north row narrower");
        double lat = g.centerY(45);
        assertEquals(geodesic(lat, 6, lat, 6 + g.cellWidth()), g.cellWidthMeters(45), 1e-4);
    }

    @Test
    void assumedWgs84GridFloatWithoutPrjReportsAssumption(@org.junit.jupiter.api.io.TempDir Path tmp)
            throws IOException {
        java.nio.file.Files.copy(TestDems.DEM_DIR.resolve(TestDems.LUXEMBOURG + ".flt"), tmp.resolve("l.flt"));
        java.nio.file.Files.copy(TestDems.DEM_DIR.resolve(TestDems.LUXEMBOURG + ".hdr"), tmp.resolve("l.hdr"));
        GridGeometry g = DemReader.inspect(tmp.resolve("l.flt")).geometry();
        assertTrue(g.crs().assumed());
        assertTrue(g.crs().isGeographic());
        java.nio.file.Files.copy(TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ".flt"), tmp.resolve("u.flt"));
        java.nio.file.Files.copy(TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ".hdr"), tmp.resolve("u.hdr"));
        GridGeometry u = DemReader.inspect(tmp.resolve("u.flt")).geometry();
        assertEquals(CrsInfo.Kind.UNKNOWN, u.crs().kind(), "UTM numbers are not degrees");
        assertTrue(!u.hasMetricUnits());
    }
}
