package io.github.jdem846.io.mosaic;

import io.github.jdem846.raster.NoData;
import java.nio.file.Path;

/**
 * One file of a mosaic and where its cells go: the {@code width × height} cells starting at column
 * {@code srcCol}, row {@code srcRow} of the file are the cells starting at column {@code col}, row {@code row}
 * of the mosaic.
 *
 * @param header      the file's header
 * @param noData      stored values that are no-data besides the file's own (a VRT's {@code NoDataValue} and
 *                    {@code NODATA}); NaN is always no-data
 * @param srcCol      first column read in the file
 * @param srcRow      first row read in the file
 * @param col         its column in the mosaic
 * @param row         its row in the mosaic
 * @param width       columns
 * @param height      rows
 */
record Member(MemberHeader header, float[] noData, int srcCol, int srcRow, int col, int row, int width,
              int height) {

    Member {
        noData = noData.clone();
    }

    /** A whole file at ({@code col}, {@code row}) with no no-data of its own besides the file's. */
    static Member whole(MemberHeader header, int col, int row) {
        return new Member(header, new float[0], 0, 0, col, row, header.info().width(), header.info().height());
    }

    /** @return the data file */
    Path file() {
        return header.data();
    }

    /** @return the stored values that read as no-data: the file's declared one, then {@link #noData} */
    float[] allNoData() {
        double declared = header.info().noDataOrNaN();
        if (Double.isNaN(declared)) {
            return noData.clone();
        }
        float[] all = new float[noData.length + 1];
        all[0] = NoData.toFloat32(declared);
        System.arraycopy(noData, 0, all, 1, noData.length);
        return all;
    }

    /** @return true when its cells in the mosaic meet those of {@code other} */
    boolean overlaps(Member other) {
        return col < other.col + other.width && other.col < col + width && row < other.row + other.height
                && other.row < row + height;
    }

    /** @return true when its cells in the mosaic meet the rectangle */
    boolean meets(int c, int r, int w, int h) {
        return col < c + w && c < col + width && row < r + h && r < row + height;
    }
}
