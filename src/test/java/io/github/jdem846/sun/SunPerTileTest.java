package io.github.jdem846.sun;

import static io.github.jdem846.sun.SolarCalculatorTest.assertMessage;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.TestDems;
import java.time.ZonedDateTime;
import org.junit.jupiter.api.Test;

class SunPerTileTest {

    private static final ZonedDateTime NOON_UTC = ZonedDateTime.parse("2024-06-21T12:00Z");

    /** A geographic grid of 1°-cells: columns lon0…lon0+w, rows lat0 (north) … lat0−h. */
    private static GridGeometry degrees(int w, int h, double westLon, double northLat, double cell) {
        return new GridGeometry(w, h, westLon, northLat, cell, cell, CrsInfo.geographic("WGS 84", 4326,
                Ellipsoid.WGS84), PixelAnchor.CORNER);
    }

    @Test
    void eachTileGetsTheSunAtItsCentre() {
        GridGeometry g = degrees(10, 7, 0, 55, 1); // 0…10 E, 48…55 N
        SunPerTile tiles = SunPerTile.compute(g, LatLonLocator.geographic(g), 4, 3, NOON_UTC, Observer.SEA_LEVEL);
        assertEquals(3, tiles.tilesAcross()); // 4 + 4 + 2 columns
        assertEquals(3, tiles.tilesDown()); // 3 + 3 + 1 rows
        // tile (1, 0): columns 4..7 → lon 4…8, centre 6 E; rows 0..2 → lat 55…52, centre 53.5 N (worked by hand)
        SunPosition expected = SolarCalculator.position(NOON_UTC, 53.5, 6, Observer.SEA_LEVEL);
        assertEquals(expected, tiles.forTile(1, 0));
        // partial corner tile (2, 2): columns 8..9 → centre 9 E; row 6 → centre 48.5 N
        assertEquals(SolarCalculator.position(NOON_UTC, 48.5, 9, Observer.SEA_LEVEL), tiles.forTile(2, 2));
        assertSame(tiles.forTile(2, 2), tiles.forCell(9, 6));
        assertSame(tiles.forTile(1, 0), tiles.forCell(4, 2));
        assertSame(tiles.forTile(0, 1), tiles.forCell(3, 3));
        assertEquals(tiles.forCell(5, 1).toLightDirection(), tiles.lightForCell(5, 1));
    }

    @Test
    void singleSunIsTheGridCentreAndPerRowFollowsLatitude() {
        GridGeometry g = degrees(20, 20, -10, 60, 1); // 10 W…10 E, 40…60 N
        SunPerTile single = SunPerTile.single(g, LatLonLocator.geographic(g), NOON_UTC, Observer.SEA_LEVEL);
        assertEquals(SolarCalculator.position(NOON_UTC, 50, 0, Observer.SEA_LEVEL), single.forCell(0, 19));
        assertEquals(0, single.azimuthSpreadDegrees());
        SunPerTile rows = SunPerTile.perRow(g, LatLonLocator.geographic(g), NOON_UTC, Observer.SEA_LEVEL);
        assertEquals(20, rows.tilesDown());
        // near noon on the June solstice the sun stands higher the further south: elevation grows with the row
        for (int r = 1; r < 20; r++) {
            assertTrue(rows.forCell(0, r).elevationDegrees() > rows.forCell(0, r - 1).elevationDegrees());
        }
        // 20° of latitude at transit ≈ 19.5° of elevation (noon at 0° E is 12:02 UTC)
        assertEquals(19, rows.elevationSpreadDegrees(), 0.7);
    }

    @Test
    void realGeographicDemLuxembourg() {
        GridGeometry g = TestDems.load(TestDems.LUXEMBOURG).geometry(); // 95 × 90 cells of 30″, about 66 × 83 km
        SunPerTile tiles = SunPerTile.compute(g, LatLonLocator.geographic(g), 32, 32, NOON_UTC, Observer.SEA_LEVEL);
        assertEquals(9, tiles.tilesAcross() * tiles.tilesDown());
        // over 0.53° of longitude the sun moves about 0.5–1° in azimuth at noon at 49.8° N, and ~0.5° in elevation
        // over 0.5° of latitude
        assertTrue(tiles.azimuthSpreadDegrees() > 0.2 && tiles.azimuthSpreadDegrees() < 2,
                "azimuth spread " + tiles.azimuthSpreadDegrees());
        assertTrue(tiles.elevationSpreadDegrees() > 0.2 && tiles.elevationSpreadDegrees() < 1,
                "elevation spread " + tiles.elevationSpreadDegrees());
    }

    @Test
    void gridAcrossTheAntimeridianWrapsLongitudes() {
        GridGeometry g = degrees(10, 2, 175, 1, 1); // 175 E … 185 E (= 175 W)
        SunPerTile tiles = SunPerTile.compute(g, LatLonLocator.geographic(g), 1, 2, NOON_UTC, Observer.SEA_LEVEL);
        // column 7 is centred on 182.5 E = 177.5 W
        assertEquals(SolarCalculator.position(NOON_UTC, 0, -177.5, Observer.SEA_LEVEL), tiles.forTile(7, 0));
    }

    @Test
    void azimuthSpreadIsCircularAcrossNorth() {
        // midnight sun at 85° N around local midnight at 0° E: azimuths straddle 0/360, the true spread is small
        GridGeometry g = degrees(20, 2, -10, 86, 1);
        ZonedDateTime midnight = ZonedDateTime.parse("2024-06-21T00:00Z");
        SunPerTile tiles = SunPerTile.compute(g, LatLonLocator.geographic(g), 1, 2, midnight, Observer.SEA_LEVEL);
        // west of 0° E it is still before local midnight (sun north-west), east of it after (north-east)
        assertTrue(tiles.forTile(0, 0).azimuthDegrees() > 340, "west column " + tiles.forTile(0, 0));
        assertTrue(tiles.forTile(19, 0).azimuthDegrees() < 20, "east column " + tiles.forTile(19, 0));
        assertTrue(tiles.azimuthSpreadDegrees() < 25, "spread " + tiles.azimuthSpreadDegrees());
    }

    @Test
    void gridConvergenceOfARotatedGridIsRemovedFromTheLight() {
        // a grid of 30 m cells whose "up" points 3° east of true north, mapped equirectangularly about its centre
        // (50 N, 6 E) on a sphere: at the centre the true bearing of grid-up is exactly 3°
        double theta = Math.toRadians(3);
        double r = 6_371_000;
        LatLonLocator rotated = (c, w) -> {
            double col = c - 99.5;
            double row = w - 99.5;
            double east = 30 * (col * Math.cos(theta) - row * Math.sin(theta));
            double north = 30 * (-col * Math.sin(theta) - row * Math.cos(theta));
            return new double[] {50 + Math.toDegrees(north / r),
                6 + Math.toDegrees(east / (r * Math.cos(Math.toRadians(50))))};
        };
        GridGeometry g = new GridGeometry(200, 200, 0, 6000, 30, 30,
                CrsInfo.projected("local on a sphere", null, 1, Ellipsoid.sphere("sphere", r)), PixelAnchor.CORNER);
        SunPerTile tiles = SunPerTile.single(g, rotated, NOON_UTC, Observer.SEA_LEVEL);
        assertEquals(3, tiles.gridConvergenceDegrees(0, 0), 1e-6);
        assertEquals(tiles.forTile(0, 0).azimuthDegrees() - 3, tiles.lightForTile(0, 0).azimuthDegrees(), 1e-6);
        assertEquals(tiles.forTile(0, 0).elevationDegrees(), tiles.lightForCell(199, 0).elevationDegrees(), 0);
    }

    @Test
    void geographicGridsHaveNoConvergence() {
        GridGeometry g = degrees(10, 10, 0, 60, 1);
        SunPerTile tiles = SunPerTile.compute(g, LatLonLocator.geographic(g), 5, 5, NOON_UTC, Observer.SEA_LEVEL);
        assertEquals(0, tiles.gridConvergenceDegrees(1, 1), 0);
        assertEquals(tiles.forTile(1, 1).toLightDirection(), tiles.lightForTile(1, 1));
    }

    @Test
    void utmConvergenceMatchesTheTransverseMercatorFormula() throws Exception {
        // Apache SIS's UTM 32N inverse as the locator; γ = atan(tan(λ − λ0)·sin φ) to first order (λ0 = 9° E)
        var utm = org.apache.sis.referencing.CommonCRS.WGS84.universal(50, 6);
        var toGeo = org.apache.sis.referencing.CRS.findOperation(utm,
                org.apache.sis.referencing.CommonCRS.WGS84.geographic(), null).getMathTransform();
        double x0 = 290_000; // about 6.1° E at 50° N
        double y0 = 5_560_000;
        LatLonLocator locator = (col, row) -> {
            double[] p = {x0 + (col + 0.5) * 30, y0 - (row + 0.5) * 30};
            try {
                toGeo.transform(p, 0, p, 0, 1);
            } catch (org.opengis.referencing.operation.TransformException e) {
                throw new IllegalStateException(e);
            }
            return p; // SIS geographic(): latitude, longitude
        };
        GridGeometry g = GridGeometry.metric(100, 100, 30);
        SunPerTile tiles = SunPerTile.single(g, locator, NOON_UTC, Observer.SEA_LEVEL);
        double[] centre = locator.latLon(49.5, 49.5);
        double expected = Math.toDegrees(Math.atan(Math.tan(Math.toRadians(centre[1] - 9))
                * Math.sin(Math.toRadians(centre[0]))));
        assertEquals(expected, tiles.gridConvergenceDegrees(0, 0), 0.02);
        assertTrue(expected < -2, "west of the central meridian grid north points west of true north: " + expected);
    }

    @Test
    void customLocatorAndRefusals() {
        GridGeometry metric = GridGeometry.metric(100, 100, 30);
        assertMessage(() -> LatLonLocator.geographic(metric), "latitude and longitude");
        LatLonLocator fixed = LatLonLocator.of((col, row) -> new double[] {45 + row / 1000, 7 + col / 1000});
        SunPerTile tiles = SunPerTile.compute(metric, fixed, 50, 50, NOON_UTC, Observer.SEA_LEVEL);
        assertEquals(SolarCalculator.position(NOON_UTC, 45 + 24.5 / 1000, 7 + 74.5 / 1000, Observer.SEA_LEVEL),
                tiles.forTile(1, 0));
        LatLonLocator broken = (col, row) -> new double[] {95, 0};
        assertMessage(() -> SunPerTile.compute(metric, broken, 50, 50, NOON_UTC, Observer.SEA_LEVEL), "tile (0, 0)");
        assertMessage(() -> SunPerTile.compute(metric, fixed, 0, 50, NOON_UTC, Observer.SEA_LEVEL), "tile size");
    }
}
