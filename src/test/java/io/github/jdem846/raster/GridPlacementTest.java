package io.github.jdem846.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import org.junit.jupiter.api.Test;

/** A window remembers where it lies in the grid it was cut from, through windows of windows and crops. */
class GridPlacementTest {

    private static final GridGeometry ROOT = new GridGeometry(400, 300, 500_000, 4_000_000, 30, 30,
            CrsInfo.projected("UTM", 32611, 1, Ellipsoid.WGS84), PixelAnchor.CORNER);

    @Test
    void aGridIsItsOwnRoot() {
        assertEquals(new GridGeometry.Placement(0, 0, 400, 300), ROOT.placement());
        assertEquals(new GridGeometry.Placement(0, 0, 7, 5), GridGeometry.metric(7, 5, 10).placement());
    }

    @Test
    void windowsAccumulateTheirOffsets() {
        GridGeometry w = ROOT.window(100, 50, 200, 120).window(-10, 7, 30, 20);
        assertEquals(new GridGeometry.Placement(90, 57, 400, 300), w.placement());
        assertEquals(ROOT.originX() + 90 * 30, w.originX(), 1e-9);
        assertEquals(w.placement(), w.withCrs(CrsInfo.UNKNOWN).placement(), "a new CRS keeps the placement");
        Dem dem = new Dem(new float[400 * 300], ROOT);
        assertEquals(new GridGeometry.Placement(12, 34, 400, 300), dem.crop(12, 34, 50, 60).geometry().placement());
    }

    @Test
    void aDecimatedGridStartsAfresh() {
        GridGeometry d = ROOT.window(100, 50, 200, 120).decimate(3, 3);
        assertEquals(new GridGeometry.Placement(0, 0, d.width(), d.height()), d.placement());
    }
}
