package io.github.jdem846.sun;

import io.github.jdem846.geo.LatLon;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.GridGeometry;
import java.time.ZonedDateTime;
import java.util.Objects;

/**
 * The sun at a date and time as the renderer's {@link LightField}: one sun seen from the grid's centre (the
 * original's default), one per tile from each tile's own latitude and longitude, or one seen from an explicit
 * place when the grid's CRS is unknown. Azimuths are in the grid's frame (grid convergence applied).
 */
public final class SunLightField implements LightField {

    private final SunPerTile suns;
    private final LightDirection central;
    private final SunPosition centralSun;
    private final boolean uniform;

    private SunLightField(SunPerTile suns, LightDirection central, SunPosition centralSun, boolean uniform) {
        this.suns = suns;
        this.central = central;
        this.centralSun = centralSun;
        this.uniform = uniform;
    }

    /**
     * The sun over {@code grid} at {@code time}.
     *
     * @param grid the grid the light falls on; without {@code place}, its CRS places the cells on the globe
     * @param time the instant, in any zone
     * @param place    where to compute one sun for the whole grid, or {@code null} to place the cells by the CRS
     * @param tileSize cells per tile edge for a sun per tile; 0 for one sun at the grid's centre
     * @param observer height, air and ΔT of the observer
     * @return one sun seen from {@code place}, or the suns of the grid's cells (one, or one per tile) turned into
     *     the grid's frame
     * @throws IllegalArgumentException when neither the CRS nor {@code place} gives a position (the message says to
     *                                  pass {@code --sun-at LAT,LON})
     */
    public static SunLightField of(GridGeometry grid, ZonedDateTime time, LatLon place, int tileSize,
                                   Observer observer) {
        Objects.requireNonNull(grid, "grid");
        Objects.requireNonNull(time, "time");
        Objects.requireNonNull(observer, "observer");
        if (place != null) {
            SunPosition p = SolarCalculator.position(time, place, observer);
            return new SunLightField(null, p.toLightDirection(), p, true);
        }
        LatLonLocator locator;
        try {
            locator = LatLonLocator.forGrid(grid);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("cannot place the DEM on the globe to compute the sun: "
                    + e.getMessage());
        }
        SunPerTile suns = tileSize > 0 ? SunPerTile.compute(grid, locator, tileSize, tileSize, time, observer)
                : SunPerTile.single(grid, locator, time, observer);
        int cc = grid.width() / 2;
        int cr = grid.height() / 2;
        return new SunLightField(suns, suns.lightForCell(cc, cr), suns.forCell(cc, cr),
                tileSize <= 0 || (suns.tilesAcross() == 1 && suns.tilesDown() == 1));
    }

    @Override
    public LightDirection at(int col, int row) {
        return uniform ? central : suns.lightForCell(col, row);
    }

    @Override
    public LightDirection central() {
        return central;
    }

    @Override
    public boolean isUniform() {
        return uniform;
    }

    /** {@return the sun on the sky at the grid's centre (for the twilight fade and for reporting)} */
    public SunPosition centralSun() {
        return centralSun;
    }
}
