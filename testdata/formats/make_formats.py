#!/usr/bin/python3
"""Builds testdata/formats/ from testdata/dem/ with Debian's GDAL 3.6.2 Python bindings (see README.md).

Run from this folder: /usr/bin/python3 make_formats.py
"""
import os
import subprocess

import numpy as np
from osgeo import gdal

gdal.UseExceptions()
VOLCANO = "../dem/maungawhau-volcano_10m_nztm-approx.tif"
LUX = "../dem/luxembourg_srtm30s_wgs84.tif"


def translate(src, dst, *args):
    subprocess.run(["gdal_translate", "-q", *args, src, dst], check=True)


def write_like(src_path, dst, array_bands, gdal_type, options=(), nodata=None, srs=None, geotransform=None):
    """Writes the given bands with the georeferencing of src_path (or the given one)."""
    src = gdal.Open(src_path)
    rows, cols = array_bands[0].shape
    drv = gdal.GetDriverByName("GTiff")
    ds = drv.Create(dst, cols, rows, len(array_bands), gdal_type, list(options))
    ds.SetGeoTransform(geotransform or src.GetGeoTransform())
    ds.SetProjection(srs if srs is not None else src.GetProjection())
    for i, a in enumerate(array_bands):
        b = ds.GetRasterBand(i + 1)
        b.WriteArray(a)
        if nodata is not None:
            b.SetNoDataValue(nodata)
    ds.FlushCache()
    ds = None


v = gdal.Open(VOLCANO).ReadAsArray().astype(np.int64)  # 87 x 61, 94..195

# Sample types TwelveMonkeys decodes to other Java buffer types.
write_like(VOLCANO, "volcano_uint8.tif", [v.astype(np.uint8)], gdal.GDT_Byte)
write_like(VOLCANO, "volcano_int8_minus100.tif", [(v - 100).astype(np.int8)], gdal.GDT_Byte,
           options=["PIXELTYPE=SIGNEDBYTE"])
u16 = v.astype(np.uint16) * 300          # 28200..58500: above 32767, so signedness matters
u16[0, 0] = 65535
u16[86, 60] = 65535
write_like(VOLCANO, "volcano_uint16_times300_nodata65535.tif", [u16], gdal.GDT_UInt16, nodata=65535)
write_like(VOLCANO, "volcano_int32_minus1000.tif", [(v - 1000).astype(np.int32)], gdal.GDT_Int32,
           options=["COMPRESS=DEFLATE", "PREDICTOR=2"])
write_like(VOLCANO, "volcano_uint32_times20000000.tif", [v.astype(np.uint32) * 20000000], gdal.GDT_UInt32)
write_like(VOLCANO, "volcano_float64_times1.5.tif", [v.astype(np.float64) * 1.5], gdal.GDT_Float64,
           options=["TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16", "COMPRESS=LZW", "PREDICTOR=3"])
write_like(VOLCANO, "volcano_2bands.tif", [v.astype(np.int16), np.zeros_like(v, dtype=np.int16)],
           gdal.GDT_Int16)
write_like(VOLCANO, "volcano_2bands_planar_tile16.tif", [v.astype(np.int16), np.full_like(v, -7, dtype=np.int16)],
           gdal.GDT_Int16, options=["INTERLEAVE=BAND", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16",
                                    "COMPRESS=DEFLATE"])
write_like(VOLCANO, "volcano_uint8_jpeg_q95.tif", [v.astype(np.uint8)], gdal.GDT_Byte,
           options=["COMPRESS=JPEG", "JPEG_QUALITY=95", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16"])
write_like(VOLCANO, "volcano_cint16.tif", [v.astype(np.int16)], gdal.GDT_CInt16)
write_like(VOLCANO, "volcano_rotated.tif", [v.astype(np.int16)], gdal.GDT_Int16,
           geotransform=(1756944.0, 9.96194698, 0.87155743, 5917994.0, 0.87155743, -9.96194698))

# Sparse files (SPARSE_OK): blocks that hold only no-data (or only 0 without no-data) are not written; their
# offset and byte count are 0 and readers fill them with no-data (or 0).
sparse = v.astype(np.int16)
sparse[16:48, 16:48] = -32768           # tiles (1,1), (1,2), (2,1), (2,2) of 16 x 16
sparse[80:87, 48:61] = -32768           # the partial tile in the south-east corner
write_like(VOLCANO, "volcano_sparse_tile16_nodata.tif", [sparse], gdal.GDT_Int16, nodata=-32768,
           options=["SPARSE_OK=TRUE", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16", "COMPRESS=DEFLATE"])
zeros = v.astype(np.int16)
zeros[8:24, :] = 0                      # strips 1 and 2 of 8 rows
write_like(VOLCANO, "volcano_sparse_strip8_zeros.tif", [zeros], gdal.GDT_Int16,
           options=["SPARSE_OK=TRUE", "BLOCKYSIZE=8", "COMPRESS=LZW", "PREDICTOR=2"])

# Predictors on every integer width and on separate planes: jdem846 undoes predictors 2 and 3 itself.
write_like(VOLCANO, "volcano_uint8_deflate_pred2.tif", [v.astype(np.uint8)], gdal.GDT_Byte,
           options=["COMPRESS=DEFLATE", "PREDICTOR=2"])
write_like(VOLCANO, "volcano_int8_minus100_lzw_pred2.tif", [(v - 100).astype(np.int8)], gdal.GDT_Byte,
           options=["PIXELTYPE=SIGNEDBYTE", "COMPRESS=LZW", "PREDICTOR=2"])
write_like(VOLCANO, "volcano_uint16_times300_lzw_pred2_bigendian.tif", [v.astype(np.uint16) * 300],
           gdal.GDT_UInt16, options=["COMPRESS=LZW", "PREDICTOR=2", "ENDIANNESS=BIG"])
write_like(VOLCANO, "volcano_uint32_times20000000_deflate_pred2_tile16.tif", [v.astype(np.uint32) * 20000000],
           gdal.GDT_UInt32, options=["COMPRESS=DEFLATE", "PREDICTOR=2", "TILED=YES", "BLOCKXSIZE=16",
                                     "BLOCKYSIZE=16"])
write_like(VOLCANO, "volcano_2bands_planar_float32_pred3_tile16.tif",
           [v.astype(np.float32) + np.float32(0.25), np.full(v.shape, -7.5, dtype=np.float32)], gdal.GDT_Float32,
           options=["INTERLEAVE=BAND", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16", "COMPRESS=DEFLATE",
                    "PREDICTOR=3"])

# LZW without a predictor (jdem846 decompresses LZW itself).
write_like(VOLCANO, "volcano_float32_plus0.5_lzw_tile16.tif", [v.astype(np.float32) + np.float32(0.5)],
           gdal.GDT_Float32, options=["COMPRESS=LZW", "TILED=YES", "BLOCKXSIZE=16", "BLOCKYSIZE=16"])
write_like(VOLCANO, "volcano_int16_lzw_strip8_bigendian.tif", [v.astype(np.int16)], gdal.GDT_Int16,
           options=["COMPRESS=LZW", "BLOCKYSIZE=8", "ENDIANNESS=BIG"])

# PixelIsPoint: the same grid, georeferenced on cell centres.
translate(VOLCANO, "volcano_pixelispoint.tif", "-mo", "AREA_OR_POINT=Point")
translate(VOLCANO, "volcano_int16_decimetres_scale0.1_offset50_nodata440.tif", "-ot", "Int16", "-scale", "94", "195",
          "440", "1450", "-a_scale", "0.1", "-a_offset", "50", "-a_nodata", "440")

# US survey feet: EPSG:2227 (not in Apache SIS's offline EPSG subset) and a user-defined TM in feet.
translate(VOLCANO, "volcano_epsg2227_ftus.tif", "-a_srs", "EPSG:2227")
translate(VOLCANO, "volcano_userdefined_tm_ftus.tif", "-a_srs",
          "+proj=tmerc +lat_0=0 +lon_0=173 +k=0.9996 +x_0=1600000 +y_0=10000000 +ellps=GRS80 +units=us-ft +no_defs")

# Other formats.
translate(VOLCANO, "volcano.asc", "-of", "AAIGrid")
translate(LUX, "luxembourg.asc", "-of", "AAIGrid")
translate(VOLCANO, "volcano.bil", "-of", "EHdr")
translate(LUX, "luxembourg.bil", "-of", "EHdr")

for f in os.listdir("."):
    if f.endswith(".aux.xml") or f.endswith(".stx"):
        os.remove(f)
