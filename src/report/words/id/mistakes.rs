//! The mistake catalog's descriptions in Bahasa Indonesia, by the
//! mistake's code (the catalog, `tutor::diagnose::CATALOG`, keeps the
//! English ones). A word table: long on purpose.

/// The Indonesian description of a catalog code (a test checks that every
/// code of the catalog has one).
pub(super) fn mistake(code: &str) -> Option<&'static str> {
    Some(match code {
        "cross_order" => {
            "u = n × Vup, bukan Vup × n (u, dan bersamanya v = n × u, berganti tanda)"
        }
        "n_reversed" => {
            "n dihitung dari Pr − Pe, bukan Pe − Pr (kamera menghadap ke arah yang salah)"
        }
        "n_not_normalized" => {
            "n = Pe − Pr tidak dibagi dengan |Pe − Pr| (v = n × u pun ikut memiliki panjang itu)"
        }
        "u_not_normalized" => {
            "u = Vup × n tidak dibagi dengan |Vup × n| (v = n × u pun ikut memiliki panjang itu)"
        }
        "fovy_not_halved" => "tan(fovy) dipakai untuk viewing window, bukan tan(fovy/2)",
        "degrees_as_radians" => "sudut dalam derajat dimasukkan ke tan seolah-olah dalam radian",
        "height_is_half_extent" => {
            "setengah ukuran near·tan(fovy/2) (h pada teks) diberikan sebagai tinggi viewing window (dan aspect·h sebagai lebarnya)"
        }
        "height_as_half_extent" => {
            "near·tan(fovy/2) dianggap tinggi penuh, sehingga tepi-tepi viewing window berada pada setengah jarak yang benar"
        }
        "d_sign" => "tanda d salah (bidang proyeksi z = +near, bukan z = −near)",
        "matrix_transposed" => "matriks pandang ditulis tertranspos (konvensi vektor baris P·M)",
        "outcode_reversed" => {
            "bit-bit outcode ditulis dengan urutan terbalik (bit 1 paling kiri, bukan paling kanan)"
        }
        "endpoint_kept" => {
            "titik ujung di luar kotak dipertahankan, bukan titik potong yang menggantikannya"
        }
        "reflect_plus_l" => "R dihitung sebagai 2N(L·N) + L, bukan 2N(L·N) − L",
        "specular_no_max" => {
            "komponen specular tanpa max(·, 0): cos β yang negatif dipangkatkan n"
        }
        "pixel_y_from_top" => {
            "py piksel diukur dari tepi atas (H − py), seperti baris berkas gambar dihitung, bukan dari tepi bawah"
        }
        "eye_no_translation" => {
            "koordinat kamera diambil sebagai (u·P, v·P, n·P), Peye tidak dikurangkan (matriks transformasi pandang tanpa translasinya, serta proyeksi dan piksel yang mengikutinya)"
        }
        "aspect_inverted" => {
            "tepi kanan viewing window diambil sebagai top / aspect, bukan aspect·top (lebarnya 2·top/aspect, dan piksel yang mengikutinya)"
        }
        "light_not_normalized" => {
            "L tidak dibagi dengan |L|: cos α = L·N dengan vektor cahaya apa adanya (serta R = 2N(L·N) − L, cos β dan komponen-komponen yang mengikutinya)"
        }
        "normal_not_normalized" => {
            "N tidak dibagi dengan |N|: cos α = L·N dengan normal apa adanya (serta R, cos β dan komponen-komponen yang mengikutinya)"
        }
        "copied_misprint" => {
            "nilai yang dicetak sumber, yang menurut erratanya salah (lihat erratanya)"
        }
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use crate::tutor::diagnose::CATALOG;

    #[test]
    fn every_mistake_of_the_catalog_has_its_indonesian_words() {
        for m in CATALOG {
            let id = super::mistake(m.code);
            assert!(id.is_some(), "no Indonesian text for {}", m.code);
            assert_ne!(id, Some(m.description), "{}", m.code);
        }
    }
}
