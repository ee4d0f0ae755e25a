package io.github.jdem846.raster;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.geo.GeoLocator;
import io.github.jdem846.geo.LatLon;
import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.geo.WebMercator;
import java.util.Objects;
import java.util.Optional;

/**
 * The position of a north-up grid on the ground: an axis-aligned affine transform from (column, row) to world
 * coordinates, the CRS, and the metric size of a cell.
 *
 * <p>Column {@code c} and row {@code r} address the cell whose outer upper-left (north-west) corner is at
 * {@code (originX + c·cellWidth, originY − r·cellHeight)}; its centre is half a cell further in. Row 0 is north.
 * Files that anchor coordinates on cell centres (PixelIsPoint, {@code xllcenter}) are converted to this corner form
 * when read; {@link #declaredAnchor()} remembers what the file said.
 *
 * <p>Metric cell size: for a projected CRS it is the cell size times the linear unit in metres, the same for every
 * row. For a geographic CRS it is computed per row on the CRS's ellipsoid (WGS 84 when unnamed): east–west
 * N(φ)·cos φ·Δλ, north–south the meridian arc across the row. With unknown units it is the cell size itself
 * ({@link #hasMetricUnits()} is then false and callers should say so). A Web Mercator grid can be asked for its
 * ground sizes instead, per row like a geographic grid ({@link #withGroundCellSizes()}).
 */
public final class GridGeometry {

    private final int width;
    private final int height;
    private final double originX;
    private final double originY;
    private final double cellWidth;
    private final double cellHeight;
    private final CrsInfo crs;
    private final PixelAnchor declaredAnchor;
    private final Placement placement;
    /** True: metric sizes are lengths on the ground of a Web Mercator grid ({@link #withGroundCellSizes()}). */
    private final boolean groundSizes;
    /** The origin of the root grid ({@link #placement}): cell centres are computed from it, see {@link #centerY}. */
    private final double rootOriginX;
    private final double rootOriginY;
    private volatile Optional<GeoLocator> locator; // derived from crs, built on first use

    /**
     * A grid placed in a CRS, not cut from another.
     *
     * @param width          number of columns, ≥ 1
     * @param height         number of rows, ≥ 1
     * @param originX        world x of the west edge of column 0
     * @param originY        world y of the north edge of row 0
     * @param cellWidth      positive cell width in CRS units
     * @param cellHeight     positive cell height in CRS units (rows go south)
     * @param crs            the CRS ({@link CrsInfo#UNKNOWN} when unknown)
     * @param declaredAnchor what the source file declared
     */
    public GridGeometry(int width, int height, double originX, double originY, double cellWidth, double cellHeight,
                        CrsInfo crs, PixelAnchor declaredAnchor) {
        this(width, height, originX, originY, cellWidth, cellHeight, crs, declaredAnchor,
                new Placement(0, 0, Math.max(width, 1), Math.max(height, 1)), false, originX, originY);
    }

    private GridGeometry(GridGeometry g, int width, int height, double originX, double originY, Placement placement) {
        this(width, height, originX, originY, g.cellWidth, g.cellHeight, g.crs, g.declaredAnchor, placement,
                g.groundSizes, g.rootOriginX, g.rootOriginY);
    }

    private GridGeometry(int width, int height, double originX, double originY, double cellWidth, double cellHeight,
                         CrsInfo crs, PixelAnchor declaredAnchor, Placement placement, boolean groundSizes,
                         double rootOriginX, double rootOriginY) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("grid size must be at least 1×1, got " + width + "×" + height);
        }
        if (!(cellWidth > 0) || !(cellHeight > 0) || Double.isInfinite(cellWidth) || Double.isInfinite(cellHeight)) {
            throw new IllegalArgumentException("cell size must be positive and finite, got " + cellWidth + " × "
                    + cellHeight);
        }
        if (!Double.isFinite(originX) || !Double.isFinite(originY)) {
            throw new IllegalArgumentException("grid origin must be finite, got " + originX + ", " + originY);
        }
        this.width = width;
        this.height = height;
        this.originX = originX;
        this.originY = originY;
        this.cellWidth = cellWidth;
        this.cellHeight = cellHeight;
        this.crs = Objects.requireNonNull(crs, "crs");
        this.declaredAnchor = Objects.requireNonNull(declaredAnchor, "declaredAnchor");
        this.placement = placement;
        this.groundSizes = groundSizes;
        this.rootOriginX = rootOriginX;
        this.rootOriginY = rootOriginY;
    }

    /**
     * Where a grid lies in the grid it was cut from by {@link #window} (through any number of windows): its first
     * column and row there, and that grid's size. A grid made any other way is its own root: (0, 0, its size).
     * Algorithms whose sampling depends on where a grid starts (the shadow sweep's lines) use it so that a window
     * gives the same answers as the grid it was cut from.
     *
     * @param col        first column in the root grid (negative when the window reaches past its west edge)
     * @param row        first row in the root grid
     * @param rootWidth  the root grid's columns
     * @param rootHeight the root grid's rows
     */
    public record Placement(int col, int row, int rootWidth, int rootHeight) {
    }

    /** {@return where this grid lies in the grid it was cut from (see {@link Placement})} */
    public Placement placement() {
        return placement;
    }

    /**
     * A grid with unknown CRS whose cells are {@code cellSizeMeters} metres square (for DEMs made in memory).
     *
     * @param width number of columns, ≥ 1
     * @param height number of rows, ≥ 1
     * @param cellSizeMeters the cells' side in metres, positive
     * @return a grid whose north-west corner is at (0, {@code height × cellSizeMeters})
     */
    public static GridGeometry metric(int width, int height, double cellSizeMeters) {
        CrsInfo local = CrsInfo.projected("local metric grid", null, 1.0, null);
        return new GridGeometry(width, height, 0, height * cellSizeMeters, cellSizeMeters, cellSizeMeters, local,
                PixelAnchor.CORNER);
    }

    /** {@return number of columns, ≥ 1} */
    public int width() {
        return width;
    }

    /** {@return number of rows, ≥ 1} */
    public int height() {
        return height;
    }

    /** {@return world x of the west edge of the grid} */
    public double originX() {
        return originX;
    }

    /** {@return world y of the north edge of the grid} */
    public double originY() {
        return originY;
    }

    /** {@return cell width in CRS units} */
    public double cellWidth() {
        return cellWidth;
    }

    /** {@return cell height in CRS units (positive)} */
    public double cellHeight() {
        return cellHeight;
    }

    /** {@return the CRS ({@link CrsInfo#UNKNOWN} when unknown)} */
    public CrsInfo crs() {
        return crs;
    }

    /** {@return whether the source file declared its georeferencing for cell corners or cell centres} */
    public PixelAnchor declaredAnchor() {
        return declaredAnchor;
    }

    /**
     * World x of the centre of column {@code col} (fractional columns allowed), computed from the root grid's
     * origin ({@link #placement}), so that a window gives its cells exactly the root's values, bit for bit.
     *
     * @param col column, from 0 at the west; fractional values lie between centres
     * @return the world x, in CRS units
     */
    public double centerX(double col) {
        return rootOriginX + (placement.col() + col + 0.5) * cellWidth;
    }

    /**
     * World y of the centre of row {@code row} (fractional rows allowed), computed from the root grid's origin as
     * {@link #centerX} is: the per-row metric sizes of a window of a latitude/longitude grid, and what is computed
     * from them, are those of the same rows of the root.
     *
     * @param row row, from 0 at the north; fractional values lie between centres
     * @return the world y, in CRS units
     */
    public double centerY(double row) {
        return rootOriginY - (placement.row() + row + 0.5) * cellHeight;
    }

    /** {@return world x of the east edge} */
    public double eastX() {
        return originX + width * cellWidth;
    }

    /** {@return world y of the south edge} */
    public double southY() {
        return originY - height * cellHeight;
    }

    /** {@return true when cell sizes in metres are known (projected with a known unit, or geographic)} */
    public boolean hasMetricUnits() {
        return crs.kind() != CrsInfo.Kind.UNKNOWN;
    }

    /**
     * East–west size in metres of a cell of row {@code row} (see the class comment).
     *
     * @param row row, from 0 at the north
     * @return the width in metres
     */
    public double cellWidthMeters(int row) {
        return switch (crs.kind()) {
            case PROJECTED -> groundSizes
                    ? crs.ellipsoidOrWgs84().parallelArcLength(WebMercator.latitude(centerY(row)),
                            WebMercator.longitudeSpan(cellWidth))
                    : cellWidth * crs.linearUnitMeters();
            case GEOGRAPHIC -> crs.ellipsoidOrWgs84().parallelArcLength(centerY(row), cellWidth);
            case UNKNOWN -> cellWidth;
        };
    }

    /**
     * North–south size in metres of a cell of row {@code row} (see the class comment).
     *
     * @param row row, from 0 at the north
     * @return the height in metres
     */
    public double cellHeightMeters(int row) {
        return switch (crs.kind()) {
            case PROJECTED -> {
                if (!groundSizes) {
                    yield cellHeight * crs.linearUnitMeters();
                }
                double north = northEdge(row);
                yield crs.ellipsoidOrWgs84().meridianArcLength(WebMercator.latitude(north),
                        WebMercator.latitude(north - cellHeight));
            }
            case GEOGRAPHIC -> {
                double north = northEdge(row);
                yield crs.ellipsoidOrWgs84().meridianArcLength(north, north - cellHeight);
            }
            case UNKNOWN -> cellHeight;
        };
    }

    /** World y of the north edge of row {@code row}, from the root grid's origin as {@link #centerY} is. */
    private double northEdge(int row) {
        return rootOriginY - ((long) placement.row() + row) * cellHeight;
    }

    /** {@return the ellipsoid used for metric sizes (the CRS's, or WGS 84)} */
    public Ellipsoid ellipsoid() {
        return crs.ellipsoidOrWgs84();
    }

    /**
     * The latitude/longitude locator of this grid's CRS (built once), or empty when the CRS cannot be located
     * (see {@link GeoLocator#forCrs}). A projected CRS a reader kept only as its EPSG code (a UTM zone) is resolved
     * by Apache SIS here, on first use.
     *
     * @return the locator, or empty
     */
    public Optional<GeoLocator> geoLocator() {
        Optional<GeoLocator> l = locator;
        if (l == null) {
            l = GeoLocator.forCrs(crs.kind() == CrsInfo.Kind.PROJECTED ? CrsResolver.complete(crs) : crs);
            locator = l;
        }
        return l;
    }

    /**
     * Latitude and longitude of the centre of cell ({@code col}, {@code row}), when the CRS allows.
     *
     * @param col column, from 0 at the west
     * @param row row, from 0 at the north
     * @return the latitude and longitude, or empty when the CRS cannot be located
     */
    public Optional<LatLon> cellCenterLatLon(int col, int row) {
        return geoLocator().map(l -> l.toLatLon(centerX(col), centerY(row)));
    }

    /**
     * For a projected grid whose projection is known: the ratio of the nominal east–west cell width in metres to
     * its true length on the ground at the grid's centre (the projection's scale factor there; ≈ 1.52 for Web
     * Mercator at 49° N, ≈ 1 for UTM). Empty when it cannot be computed (geographic or unknown CRS, projection not
     * known offline).
     *
     * @return the scale factor, or empty
     */
    public java.util.OptionalDouble groundScaleFactor() {
        if (crs.kind() != CrsInfo.Kind.PROJECTED || width < 1) {
            return java.util.OptionalDouble.empty();
        }
        try {
            int row = height / 2;
            double x0 = originX + (width / 2.0 - 0.5) * cellWidth;
            double y = centerY(row);
            Optional<LatLon> a = geoLocator().map(l -> l.toLatLon(x0, y));
            Optional<LatLon> b = geoLocator().map(l -> l.toLatLon(x0 + cellWidth, y));
            if (a.isEmpty() || b.isEmpty()) {
                return java.util.OptionalDouble.empty();
            }
            double meanLat = 0.5 * (a.get().latitude() + b.get().latitude());
            Ellipsoid e = crs.ellipsoidOrWgs84();
            double dx = e.parallelArcLength(meanLat, b.get().longitude() - a.get().longitude());
            double dy = e.meridianArcLength(a.get().latitude(), b.get().latitude());
            double ground = Math.hypot(dx, dy);
            double nominal = cellWidth * crs.linearUnitMeters();
            return ground > 0 && Double.isFinite(ground) ? java.util.OptionalDouble.of(nominal / ground)
                    : java.util.OptionalDouble.empty();
        } catch (RuntimeException e) {
            return java.util.OptionalDouble.empty(); // outside the projection's domain
        }
    }

    /** {@return the latitude/longitude box of the grid's outer edges, when the CRS allows} */
    public Optional<LatLonBox> latLonExtent() {
        return geoLocator().map(l -> l.extent(originX, southY(), eastX(), originY));
    }

    /**
     * The geometry of the sub-grid of {@code w × h} cells starting at ({@code col}, {@code row}); the window may
     * extend past the grid (callers clip first when they must not).
     *
     * @param col first column, relative to this grid
     * @param row first row, relative to this grid
     * @param w number of columns
     * @param h number of rows
     * @return the window's geometry, in the same CRS
     */
    public GridGeometry window(int col, int row, int w, int h) {
        return new GridGeometry(this, w, h, originX + col * cellWidth, originY - row * cellHeight,
                new Placement(placement.col() + col, placement.row() + row, placement.rootWidth(),
                        placement.rootHeight()));
    }

    /**
     * The geometry of this grid decimated so that each new cell covers {@code factorX × factorY} old cells: the
     * extent is kept and the last partial block, if any, counts as a whole cell.
     *
     * @param factorX old columns per new column, ≥ 1
     * @param factorY old rows per new row, ≥ 1
     * @return the decimated geometry, at least 1 × 1 cells
     */
    public GridGeometry decimate(int factorX, int factorY) {
        if (factorX < 1 || factorY < 1) {
            throw new IllegalArgumentException("decimation factors must be ≥ 1, got " + factorX + ", " + factorY);
        }
        int w = Math.max(1, (width + factorX - 1) / factorX);
        int h = Math.max(1, (height + factorY - 1) / factorY);
        return new GridGeometry(w, h, originX, originY, cellWidth * factorX, cellHeight * factorY, crs,
                declaredAnchor, new Placement(0, 0, w, h), groundSizes, originX, originY);
    }

    /**
     * This grid on {@code body} when the file did not name an ellipsoid: when the CRS names none, or was only
     * assumed from the extent (then it becomes "geographic on {@code body}", also assumed). A CRS read from the
     * file keeps its own ellipsoid, and this grid is returned unchanged.
     *
     * @param body the body the DEM lies on; not null
     * @return this grid, or a copy with the body's ellipsoid
     */
    public GridGeometry withDefaultEllipsoid(Ellipsoid body) {
        Objects.requireNonNull(body, "body");
        if (crs.ellipsoid() != null && !crs.assumed() || body.equals(crs.ellipsoid())) {
            return this;
        }
        CrsInfo c = crs.assumed()
                ? new CrsInfo(crs.kind() == CrsInfo.Kind.GEOGRAPHIC ? "geographic on " + body.name() : crs.name(),
                        null, crs.kind(), crs.linearUnitMeters(), body, null, true)
                : new CrsInfo(crs.name(), crs.epsg(), crs.kind(), crs.linearUnitMeters(), body, crs.sisCrs(), false);
        return withCrs(c);
    }

    /**
     * A copy with another CRS (ground cell sizes are kept while it is still Web Mercator).
     *
     * @param newCrs the CRS; not null
     * @return a copy with the same cells and extent
     */
    public GridGeometry withCrs(CrsInfo newCrs) {
        return new GridGeometry(width, height, originX, originY, cellWidth, cellHeight,
                Objects.requireNonNull(newCrs, "crs"), declaredAnchor, placement,
                groundSizes && WebMercator.isWebMercator(newCrs), rootOriginX, rootOriginY);
    }

    /**
     * This Web Mercator (EPSG:3857) grid with metric cell sizes measured on the ground: per row, the east–west
     * length of the cell's arc of parallel and the north–south meridian arc across the row, on the CRS's ellipsoid
     * (WGS 84), at the row's latitude. Web Mercator's nominal metres overstate ground lengths by about 1/cos φ
     * (1.41 at 45°), which is what {@link #cellWidthMeters(int)} of a projected grid otherwise reports, as gdaldem
     * uses them; hillshade slopes and cast-shadow lengths then come out true at every latitude. Map tiles use it.
     *
     * @return the grid with ground cell sizes
     * @throws IllegalArgumentException when the CRS is not Web Mercator (EPSG:3857)
     */
    public GridGeometry withGroundCellSizes() {
        if (!WebMercator.isWebMercator(crs)) {
            throw new IllegalArgumentException("ground cell sizes are known for Web Mercator (EPSG:3857) grids, "
                    + "not for " + (crs.name() != null ? crs.name() : crs.kind().toString()));
        }
        return new GridGeometry(width, height, originX, originY, cellWidth, cellHeight, crs, declaredAnchor,
                placement, true, rootOriginX, rootOriginY);
    }

    /** {@return true when metric cell sizes are measured on the ground ({@link #withGroundCellSizes()})} */
    public boolean hasGroundCellSizes() {
        return groundSizes;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof GridGeometry g && width == g.width && height == g.height
                && Double.compare(originX, g.originX) == 0 && Double.compare(originY, g.originY) == 0
                && Double.compare(cellWidth, g.cellWidth) == 0 && Double.compare(cellHeight, g.cellHeight) == 0
                && crs.kind() == g.crs.kind() && Objects.equals(crs.epsg(), g.crs.epsg())
                && groundSizes == g.groundSizes;
    }

    @Override
    public int hashCode() {
        return Objects.hash(width, height, originX, originY, cellWidth, cellHeight, crs.kind(), crs.epsg());
    }

    @Override
    public String toString() {
        return "GridGeometry[" + width + "×" + height + ", origin (" + originX + ", " + originY + "), cell "
                + cellWidth + " × " + cellHeight + ", " + crs.kind() + (crs.name() != null ? " " + crs.name() : "")
                + "]";
    }
}
