package io.github.jdem846.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.WebMercator;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.referencing.GeodeticCalculator;
import org.junit.jupiter.api.Test;

/**
 * Ground cell sizes of a Web Mercator grid ({@link GridGeometry#withGroundCellSizes()}) against geodesic distances
 * on WGS 84 computed by Apache SIS's {@link GeodeticCalculator} between the cells' edge points (within 2·10⁻⁵, SIS's
 * accuracy over 38 m: at the equator, where the exact length is a·Δλ, it is 4·10⁻⁶ short), row by row, from the
 * equator to 80°; nominal sizes stay what they were.
 */
class WebMercatorGroundSizeTest {

    @Test
    void groundSizesAreGeodesicLengthsPerRow() {
        double cell = 38.21851414258813; // zoom 12
        GeodeticCalculator geodesic = GeodeticCalculator.create(CommonCRS.WGS84.geographic());
        for (double lat = 0; lat <= 80; lat += 5) {
            double yNorth = WebMercator.y(lat);
            GridGeometry g = new GridGeometry(256, 256, 1.0e6, yNorth, cell, cell, WebMercator.CRS,
                    PixelAnchor.CORNER).withGroundCellSizes();
            for (int row : new int[] {0, 100, 255}) {
                double north = WebMercator.latitude(yNorth - row * cell);
                double south = WebMercator.latitude(yNorth - (row + 1) * cell);
                double mid = WebMercator.latitude(yNorth - (row + 0.5) * cell);
                double lon0 = WebMercator.longitude(1.0e6);
                double lon1 = WebMercator.longitude(1.0e6 + cell);
                geodesic.setStartGeographicPoint(mid, lon0);
                geodesic.setEndGeographicPoint(mid, lon1);
                double eastWest = geodesic.getGeodesicDistance();
                geodesic.setStartGeographicPoint(north, lon0);
                geodesic.setEndGeographicPoint(south, lon0);
                double northSouth = geodesic.getGeodesicDistance();
                assertEquals(eastWest, g.cellWidthMeters(row), eastWest * 2e-5, "east–west at " + mid + "°");
                assertEquals(northSouth, g.cellHeightMeters(row), northSouth * 2e-5, "north–south at " + mid + "°");
                // about the nominal size times cos φ, as the projection's scale factor says
                assertEquals(cell * Math.cos(Math.toRadians(mid)), g.cellWidthMeters(row),
                        cell * Math.cos(Math.toRadians(mid)) * 0.007);
                // a window keeps ground sizes, the same per row as the grid it was cut from
                assertEquals(g.cellWidthMeters(row), g.window(10, row, 5, 5).cellWidthMeters(0), 1e-9);
            }
        }
    }

    @Test
    void nominalSizesStayUnlessAskedFor() {
        GridGeometry g = new GridGeometry(10, 10, 0, WebMercator.y(60), 100, 100, WebMercator.CRS,
                PixelAnchor.CORNER);
        assertFalse(g.hasGroundCellSizes());
        assertEquals(100, g.cellWidthMeters(3), 0);
        GridGeometry ground = g.withGroundCellSizes();
        assertTrue(ground.hasGroundCellSizes());
        assertEquals(50, ground.cellWidthMeters(5), 0.5, "cos 60° halves it");
        assertTrue(ground.decimate(2, 2).hasGroundCellSizes());
        assertFalse(ground.equals(g));
        CrsInfo utm = CrsInfo.projected("WGS 84 / UTM zone 11N", 32611, 1.0, null);
        GridGeometry other = new GridGeometry(10, 10, 0, 0, 30, 30, utm, PixelAnchor.CORNER);
        assertThrows(IllegalArgumentException.class, other::withGroundCellSizes);
        assertFalse(ground.withCrs(utm).hasGroundCellSizes());
    }
}
